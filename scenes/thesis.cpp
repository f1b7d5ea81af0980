// SPDX-License-Identifier: MIT
#include "scenes/thesis.hpp"

#include <cmath>
#include <string>
#include <vector>

#include "scenes/gas.hpp"
#include "scenes/random.hpp"

namespace sparsedyn::scenes {
namespace {

// The shapes, orientations and velocities use their own stream, apart from the placement's
// (the gas placement seeds std::mt19937_64 with the seed itself).
constexpr std::uint64_t kStreamSalt = 0x9e3779b97f4a7c15ULL;
// Normalising a quaternion may land one ulp off norm 1; the scene reader keeps a quaternion of
// norm exactly 1 as it is, so we renormalise until it is (or draw again) and the file reads back
// bit for bit.
constexpr int kNormaliseAttempts = 4;

Status Check(const ThesisOptions& o) {
  if (o.n == 0) return Error{"thesis: n must be >= 1"};
  if (!(o.packing > 0 && o.packing < M_PI / 6)) {
    return Error{"thesis: packing fraction must be in (0, pi/6), got " + std::to_string(o.packing)};
  }
  if (o.shape_pool == 0) return Error{"thesis: shape_pool must be >= 1"};
  if (!(o.min_faces >= 4 && o.min_faces <= o.max_faces)) {
    return Error{"thesis: face counts must satisfy 4 <= min_faces <= max_faces"};
  }
  if (!(o.mean_speed >= 0 && o.max_spin >= 0 && o.density > 0 && o.duration >= 0)) {
    return Error{"thesis: mean_speed, max_spin, duration must be >= 0 and density > 0"};
  }
  return Status::Ok();
}

// A random_convex spec of bounding radius 1, built and canonicalised by the scene reader's own
// code, so the file written later names exactly this shape.
Result<SceneShape> PoolShape(int faces, std::uint64_t shape_seed) {
  const std::string spec = R"({"generator":"random_convex","faces":)" + std::to_string(faces) +
                           R"(,"seed":)" + std::to_string(shape_seed) + R"(,"bounding_radius":1})";
  return ParseShapeSpec(spec, {}, shape_seed, "thesis shape");
}

// Uniform on SO(3): a normalised 4-d Gaussian vector is uniform on the 3-sphere.
Eigen::Quaterniond RandomOrientation(Random& random) {
  for (;;) {
    Eigen::Quaterniond q = DrawQuaternion([&] { return random.Normal(); });
    if (q.norm() < 1e-3) continue;
    for (int k = 0; k < kNormaliseAttempts && q.norm() != 1.0; ++k) q.normalize();
    if (q.norm() == 1.0) return q;
  }
}

// A uniformly random unit vector (normalised 3-d Gaussian).
Vec3 RandomDirection(Random& random) {
  for (;;) {
    const Vec3 d = DrawVector([&] { return random.Normal(); });
    if (d.norm() > 1e-3) return d.normalized();
  }
}

// Gaussian velocities, zero total momentum (mass-weighted mean removed), then scaled so the mean
// speed is exactly `mean_speed` (scaling keeps the momentum zero).
void AssignVelocities(const ThesisOptions& o, Random& random, std::vector<SceneBody>& bodies) {
  Vec3 momentum = Vec3::Zero();
  double total_mass = 0;
  for (SceneBody& b : bodies) {
    b.velocity = DrawVector([&] { return random.Normal(); });
    momentum += b.mass * b.velocity;
    total_mass += b.mass;
  }
  const Vec3 drift = bodies.size() > 1 ? Vec3(momentum / total_mass) : Vec3::Zero();
  double speed_sum = 0;
  for (SceneBody& b : bodies) {
    b.velocity -= drift;
    speed_sum += b.velocity.norm();
  }
  const double scale = speed_sum > 0 ? o.mean_speed * bodies.size() / speed_sum : 0.0;
  for (SceneBody& b : bodies) b.velocity *= scale;
}

}  // namespace

double ThesisBoxSide(const ThesisOptions& options) {
  return std::cbrt(options.n * (4.0 / 3.0 * M_PI) / options.packing);
}

Result<SceneDescription> MakeThesisScene(const ThesisOptions& options) {
  if (Status ok = Check(options); !ok) return ok.error();

  // Centres: the walled gas placement of unit spheres, which keeps every bounding sphere
  // inside the walls and apart from the others.
  GasOptions gas{.n = options.n,
                 .packing = options.packing,
                 .seed = options.seed,
                 .radius = 1.0,
                 .periodic = false};
  Result<std::vector<BodyDef>> placed = MakeGasBodies(gas);
  if (!placed) return Error{"thesis: " + placed.error().message};

  SceneDescription scene;
  scene.name = "thesis";
  scene.seed = options.seed;
  scene.packing = options.packing;
  scene.duration = options.duration;
  scene.settings.broadphase = options.broadphase;
  scene.settings.container =
      Container::WalledBox(Vec3::Zero(), Vec3::Constant(ThesisBoxSide(options)));

  // The shape pool: K hulls with face counts uniform in [min_faces, max_faces].
  Random random(options.seed ^ kStreamSalt);
  const std::uint32_t pool_size = std::min(options.shape_pool, options.n);
  const auto face_range = static_cast<std::uint64_t>(options.max_faces - options.min_faces + 1);
  std::vector<SceneShape> pool;
  pool.reserve(pool_size);
  for (std::uint32_t k = 0; k < pool_size; ++k) {
    const int faces = options.min_faces + static_cast<int>(random.Below(face_range));
    Result<SceneShape> shape = PoolShape(faces, random.Engine()());
    if (!shape) return Error{"thesis: " + shape.error().message};
    pool.push_back(std::move(*shape));
  }

  // Bodies: a pool shape each, a random orientation and spin; mass from the density. Shapes
  // enter the scene in order of first use, as the scene reader numbers them, so that a written
  // scene reads back with the same shape indices.
  std::vector<std::uint32_t> scene_index(pool_size, UINT32_MAX);
  scene.bodies.resize(options.n);
  for (std::uint32_t i = 0; i < options.n; ++i) {
    SceneBody& body = scene.bodies[i];
    const std::uint64_t k = random.Below(pool_size);
    if (scene_index[k] == UINT32_MAX) {
      scene_index[k] = static_cast<std::uint32_t>(scene.shapes.size());
      scene.shapes.push_back(pool[k]);
    }
    body.shape = scene_index[k];
    body.position = (*placed)[i].position;
    body.orientation = RandomOrientation(random);
    // The speed is drawn before the direction, in sequence: as the two operands of * their order
    // was the compiler's (see DrawVector); this is the order GCC on x86-64 took.
    const double spin = random.Uniform(0, options.max_spin);
    body.angular_velocity = RandomDirection(random) * spin;
    body.density = options.density;
    body.mass = options.density * scene.shapes[body.shape].Volume();
    body.restitution = 1.0;
    body.friction = 0.0;
  }
  AssignVelocities(options, random, scene.bodies);
  return scene;
}

}  // namespace sparsedyn::scenes
