// SPDX-License-Identifier: MIT
#include "scenes/gas.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <string>

#include "scenes/random.hpp"

namespace sparsedyn::scenes {
namespace {

// Above this packing random sequential placement gets slow (its jamming limit is ~0.38).
constexpr double kRandomPlacementMaxPacking = 0.25;
// Placement attempts per sphere before random placement gives up for the lattice start.
constexpr int kAttemptsPerSphere = 200;

// Random sequential placement with a periodic cell list: cells at least two diameters wide, so
// that the cells meeting the box of half-width one diameter around a point (2 per axis, rarely
// 3) hold every sphere it could overlap, and at most ~2n of them, so that a dilute gas does not
// allocate a cell per diameter cubed of its box. Each cell is the head of a list threaded
// through `next` (no allocation per cell).
bool PlaceAtRandom(const GasOptions& o, double side, Random& random, std::vector<Vec3>& out) {
  const double diameter = 2 * o.radius;
  const int most = std::max(1, static_cast<int>(std::cbrt(2.0 * static_cast<double>(o.n))));
  const int cells = static_cast<int>(
      std::clamp(std::floor(side / (2 * diameter)), 1.0, static_cast<double>(most)));
  const double cell = side / cells;
  constexpr std::uint32_t kEnd = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> head(static_cast<std::size_t>(cells) * cells * cells, kEnd);
  std::vector<std::uint32_t> next;
  next.reserve(o.n);
  auto wrap = [cells](int v) { return ((v % cells) + cells) % cells; };
  auto index = [&](int x, int y, int z) {
    return (static_cast<std::size_t>(wrap(z)) * cells + wrap(y)) * cells + wrap(x);
  };
  // Cell coordinates of the box [p - reach, p + reach], widened past round-off; at most `cells`
  // per axis so that no cell is visited twice.
  const double reach = diameter + 1e-9 * cell;
  auto span = [&](double x, int& first, int& count) {
    first = static_cast<int>(std::floor((x - reach) / cell));
    count = std::min(cells, static_cast<int>(std::floor((x + reach) / cell)) - first + 1);
  };
  auto free_at = [&](const Vec3& p) {
    std::array<int, 3> first{}, count{};
    for (int k = 0; k < 3; ++k) span(p[k], first[k], count[k]);
    for (int z = first[2]; z < first[2] + count[2]; ++z) {
      for (int y = first[1]; y < first[1] + count[1]; ++y) {
        for (int x = first[0]; x < first[0] + count[0]; ++x) {
          for (std::uint32_t j = head[index(x, y, z)]; j != kEnd; j = next[j]) {
            Vec3 d = out[j] - p;
            if (o.periodic) {
              for (int k = 0; k < 3; ++k) d[k] -= side * std::round(d[k] / side);
            }
            if (d.squaredNorm() < diameter * diameter) return false;
          }
        }
      }
    }
    return true;
  };
  const double lo = o.periodic ? 0.0 : o.radius;
  const double hi = o.periodic ? side : side - o.radius;
  std::uint64_t attempts = 0;
  const std::uint64_t max_attempts = static_cast<std::uint64_t>(kAttemptsPerSphere) * o.n;
  while (out.size() < o.n) {
    if (++attempts > max_attempts) return false;
    Vec3 p = DrawVector([&] { return random.Uniform(lo, hi); });
    if (!free_at(p)) continue;
    const int cx = static_cast<int>(p[0] / cell), cy = static_cast<int>(p[1] / cell),
              cz = static_cast<int>(p[2] / cell);
    std::uint32_t& first = head[index(cx, cy, cz)];
    next.push_back(first);
    first = static_cast<std::uint32_t>(out.size());
    out.push_back(p);
  }
  return true;
}

// A random subset of the sites of a simple cubic lattice filling the box.
Result<std::vector<Vec3>> PlaceOnLattice(const GasOptions& o, double side, Random& random) {
  const auto m = static_cast<std::uint32_t>(std::ceil(std::cbrt(static_cast<double>(o.n)) - 1e-9));
  const double spacing = side / m;
  const double usable = o.periodic ? spacing : (side - 2 * o.radius) / std::max(1u, m - 1);
  if (std::min(spacing, m > 1 ? usable : spacing) < 2 * o.radius) {
    return Error{"gas: packing " + std::to_string(o.packing) +
                 " is too high to place the spheres without overlap"};
  }
  std::vector<std::uint32_t> sites(static_cast<std::size_t>(m) * m * m);
  std::iota(sites.begin(), sites.end(), 0u);
  for (std::uint32_t i = 0; i < o.n; ++i) {  // partial Fisher-Yates: the first n are the pick
    std::swap(sites[i], sites[i + random.Below(sites.size() - i)]);
  }
  std::vector<Vec3> out;
  out.reserve(o.n);
  for (std::uint32_t i = 0; i < o.n; ++i) {
    const std::uint32_t s = sites[i];
    const Vec3 c(s % m, (s / m) % m, s / (m * m));
    out.push_back(o.periodic ? Vec3((c.array() + 0.5) * spacing)
                             : Vec3(o.radius + c.array() * usable));
  }
  return out;
}

}  // namespace

double GasBoxSide(const GasOptions& options) {
  const double sphere_volume = 4.0 / 3.0 * M_PI * std::pow(options.radius, 3);
  return std::cbrt(options.n * sphere_volume / options.packing);
}

Result<std::vector<BodyDef>> MakeGasBodies(const GasOptions& options) {
  if (options.n == 0) return Error{"gas: n must be >= 1"};
  if (!(options.packing > 0 && options.packing < M_PI / 6)) {
    return Error{"gas: packing fraction must be in (0, pi/6), got " +
                 std::to_string(options.packing)};
  }
  const double side = GasBoxSide(options);
  Random random(options.seed);

  std::vector<Vec3> positions;
  positions.reserve(options.n);
  bool placed = false;
  if (options.packing <= kRandomPlacementMaxPacking) {
    placed = PlaceAtRandom(options, side, random, positions);
  }
  if (!placed) {
    Result<std::vector<Vec3>> lattice = PlaceOnLattice(options, side, random);
    if (!lattice) return lattice.error();
    positions = std::move(*lattice);
  }

  // Maxwell-Boltzmann velocities, zero total momentum, scaled to exactly kT per degree of
  // freedom (3N - 3 of them once the momentum is fixed).
  std::vector<Vec3> velocities(options.n);
  const double sigma_v = std::sqrt(options.kT / options.mass);
  Vec3 mean = Vec3::Zero();
  for (Vec3& v : velocities) {
    v = DrawVector([&] { return random.Normal(); }) * sigma_v;
    mean += v;
  }
  mean /= options.n;
  double kinetic = 0;
  for (Vec3& v : velocities) {
    if (options.n > 1) v -= mean;
    kinetic += 0.5 * options.mass * v.squaredNorm();
  }
  const double dof = options.n > 1 ? 3.0 * options.n - 3.0 : 3.0;
  const double scale = kinetic > 0 ? std::sqrt(0.5 * dof * options.kT / kinetic) : 1.0;

  std::vector<BodyDef> bodies(options.n);
  for (std::uint32_t i = 0; i < options.n; ++i) {
    bodies[i].radius = options.radius;
    bodies[i].mass = options.mass;
    bodies[i].restitution = options.restitution;
    bodies[i].position = positions[i];
    bodies[i].velocity = velocities[i] * scale;
  }
  return bodies;
}

Result<World> MakeGas(const GasOptions& options, WorldSettings settings) {
  Result<std::vector<BodyDef>> bodies = MakeGasBodies(options);
  if (!bodies) return bodies.error();
  const double side = GasBoxSide(options);
  settings.container = options.periodic ? Container::PeriodicBox(Vec3::Zero(), Vec3::Constant(side))
                                        : Container::WalledBox(Vec3::Zero(), Vec3::Constant(side));
  if (Status valid = ValidateSettings(settings); !valid) return valid.error();
  World world(settings);
  for (const BodyDef& def : *bodies) {
    Result<BodyId> id = world.AddBody(def);
    if (!id) return id.error();
  }
  return world;
}

}  // namespace sparsedyn::scenes
