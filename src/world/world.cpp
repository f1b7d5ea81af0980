// SPDX-License-Identifier: MIT
#include <algorithm>
#include <bit>
#include <cmath>
#include <sstream>

#include "math/branchless.hpp"
#include "world/overlap_index.hpp"
#include "world/world_impl.hpp"

namespace sparsedyn {
namespace {

std::string Format(double x) {
  std::ostringstream out;
  out.precision(17);
  out << x;
  return out.str();
}

// Checks one body definition in isolation; the message names the body index and the field.
std::optional<Error> CheckDefinition(const BodyDef& def, std::size_t index) {
  const std::string body = "body " + std::to_string(index) + ": ";
  if (!std::isfinite(def.radius) || def.radius <= 0) {
    return Error{body + "radius must be finite and > 0, got " + Format(def.radius)};
  }
  if (!std::isfinite(def.mass) || def.mass <= 0) {
    return Error{body + "mass must be finite and > 0, got " + Format(def.mass)};
  }
  if (!std::isfinite(def.restitution) || def.restitution < 0 || def.restitution > 1) {
    return Error{body + "restitution must be in [0, 1], got " + Format(def.restitution)};
  }
  if (!std::isfinite(def.friction) || def.friction < 0) {
    return Error{body + "friction must be finite and >= 0, got " + Format(def.friction)};
  }
  const Eigen::Vector4d q = def.orientation.coeffs();
  if (!q.allFinite() || std::abs(q.norm() - 1.0) > 1e-6) {
    return Error{body + "orientation must be a finite unit quaternion, got norm " +
                 Format(q.norm())};
  }
  const struct {
    const char* name;
    const Vec3& value;
  } vectors[] = {{"position", def.position},
                 {"velocity", def.velocity},
                 {"angular_velocity", def.angular_velocity},
                 {"thrust", def.thrust}};
  for (const auto& [name, value] : vectors) {
    for (int k = 0; k < 3; ++k) {
      if (!std::isfinite(value[k])) {
        return Error{body + name + "[" + std::to_string(k) + "] must be finite, got " +
                     Format(value[k])};
      }
    }
  }
  const double envelope[] = {def.envelope.e0, def.envelope.e1, def.envelope.e2};
  for (int k = 0; k < 3; ++k) {
    if (!std::isfinite(envelope[k]) || envelope[k] < 0) {
      return Error{body + "envelope.e" + std::to_string(k) + " must be finite and >= 0, got " +
                   Format(envelope[k])};
    }
  }
  return std::nullopt;
}

}  // namespace

WallPlane BoxWall(const Container& box, int wall) {
  const int axis = wall / 2;
  Vec3 n = Vec3::Zero();
  if (wall % 2 == 0) {
    n[axis] = 1.0;  // the low wall: inside is x >= lo
    return {n, box.lo[axis]};
  }
  n[axis] = -1.0;  // the high wall: inside is -x >= -hi
  return {n, -box.hi[axis]};
}

const char* EventKindName(int k) { return kEventKindNames.at(static_cast<std::size_t>(k)).data(); }

World::Impl::Impl(const WorldSettings& settings)
    : settings_(settings),
      period_(settings.container.kind == Container::Kind::kPeriodicBox
                  ? Vec3(settings.container.hi - settings.container.lo)
                  : Vec3::Zero()),
      periodic_(settings.container.kind == Container::Kind::kPeriodicBox),
      uniform_acceleration_(settings.gravity),
      overlap_index_(settings.container.lo, period_) {}

Vec3 World::Impl::WrapIntoBox(Vec3 p) const {
  if (!periodic_) return p;
  const Vec3& lo = settings_.container.lo;
  for (int k = 0; k < 3; ++k) p[k] -= period_[k] * std::floor((p[k] - lo[k]) / period_[k]);
  return p;
}

std::optional<std::uint32_t> World::Impl::FindOverlap(const Vec3& p, double radius) const {
  auto overlaps = [&](const Vec3& q, double r) {
    const Vec3 d = MinimumImage(q - p);
    const double reach = radius + r;
    return d.squaredNorm() < reach * reach * (1 - 1e-12);
  };
  std::optional<std::uint32_t> found;
  if (!started_) {
    // Before the start every body is still at its initial position: use the spatial hash.
    overlap_index_.ForEachNear(p, radius, [&](std::uint32_t j, const Vec3& q, double r) {
      if (overlaps(q, r) && (!found || j < *found)) found = j;
    });
    return found;
  }
  // Bodies added while running (rare) are compared with every body at the current time.
  for (std::uint32_t j = 0; j < starts_.size(); ++j) {
    if (overlaps(PathOf(j).PositionAt(now_), Radius(j))) return public_of_[j];
  }
  return std::nullopt;
}

Result<BodyId> World::Impl::AddBody(const BodyDef& def) {
  const std::size_t index = starts_.size();
  if (std::optional<Error> error = CheckDefinition(def, index)) return *error;
  const std::string body = "body " + std::to_string(index) + ": ";
  const bool polyhedron = def.shape != nullptr;
  if (index > 0 && polyhedron != polyhedra_) {
    return Error{body + "a World holds spheres or polyhedra, not both (this body is a " +
                 (polyhedron ? "polyhedron" : "sphere") + ", body 0 is not)"};
  }
  if (polyhedron && !def.envelope.IsZero()) {
    return Error{body + "envelopes are for spheres; a polyhedron's path is exact"};
  }
  if (polyhedron && started_) {
    return Error{body + "polyhedra are added before the first AdvanceTo"};
  }
  std::uint32_t shape = kNoIndex;
  if (polyhedron) {
    Result<std::uint32_t> added = AddShape(def.shape);
    if (!added) return Error{body + added.error().message};
    shape = *added;
  }
  // A polyhedron's element sphere is its bounding sphere about the centroid.
  const double radius = polyhedron ? shapes_[shape].polyhedron->bounding_radius() : def.radius;

  // Inside the container.
  const Container& box = settings_.container;
  const auto sphere_inside = [&] {
    return ((def.position.array() - radius) >= box.lo.array()).all() &&
           ((def.position.array() + radius) <= box.hi.array()).all();
  };
  if (polyhedron && box.kind == Container::Kind::kWalledBox && !sphere_inside()) {
    // Only a body whose bounding sphere crosses a wall can have a vertex outside.
    const ConvexPolyhedron& poly = *shapes_[shape].polyhedron;
    const Eigen::Matrix3d rotation = def.orientation.normalized().toRotationMatrix();
    for (int v = 0; v < poly.vertex_count(); ++v) {
      const Vec3 x = rotation * poly.vertex(v) + def.position;
      for (int k = 0; k < 3; ++k) {
        if (x[k] < box.lo[k] || x[k] > box.hi[k]) {
          return Error{body + "vertex " + std::to_string(v) + " lies outside the walled box " +
                       "on axis " + std::to_string(k) + " (" + Format(x[k]) + " not in [" +
                       Format(box.lo[k]) + ", " + Format(box.hi[k]) + "])"};
        }
      }
    }
  } else if (!polyhedron && box.kind == Container::Kind::kWalledBox) {
    for (int k = 0; k < 3; ++k) {
      if (def.position[k] - radius < box.lo[k] || def.position[k] + radius > box.hi[k]) {
        return Error{body + "position[" + std::to_string(k) + "] = " + Format(def.position[k]) +
                     " puts the sphere (radius " + Format(radius) + ") outside the walled box [" +
                     Format(box.lo[k]) + ", " + Format(box.hi[k]) + "]"};
      }
    }
  } else if (box.kind == Container::Kind::kPeriodicBox) {
    for (int k = 0; k < 3; ++k) {
      if (def.position[k] < box.lo[k] || def.position[k] >= box.hi[k]) {
        return Error{body + "position[" + std::to_string(k) + "] = " + Format(def.position[k]) +
                     " is outside the periodic box [" + Format(box.lo[k]) + ", " +
                     Format(box.hi[k]) + ")"};
      }
      if (2 * radius >= 0.5 * (box.hi[k] - box.lo[k])) {
        return Error{body + "radius " + Format(radius) +
                     " is too large for the periodic box (diameter must be < half the box)"};
      }
    }
  }
  if (polyhedron) {
    double distance = 0;
    if (std::optional<std::uint32_t> other = FindPolyhedronOverlap(def, shape, distance)) {
      return Error{body + "touches or overlaps body " + std::to_string(*other) +
                   " at the start (distance " + Format(distance) + ")"};
    }
  } else if (std::optional<std::uint32_t> other = FindOverlap(def.position, def.radius)) {
    return Error{body + "overlaps body " + std::to_string(*other) +
                 " at the start (t = " + Format(now_) + ")"};
  }

  // Accepted: from here on nothing can fail.
  starts_.push_back(ElementStart{PathStart{def.position, def.velocity, now_}, GridLinks{}});
  const Vec3 acceleration = settings_.gravity + def.thrust;
  if (!own_accelerations_ && acceleration != uniform_acceleration_) {
    own_accelerations_ = true;  // the first body with a thrust of its own
    acceleration_.assign(index, uniform_acceleration_);
  }
  if (own_accelerations_) acceleration_.push_back(acceleration);
  if (!held_by_.empty()) {
    held_by_.push_back(0);
    free_acceleration_.push_back(acceleration);
  }
  if (!started_) overlap_index_.Add(def.position, radius);
  const std::array<double, 4> material{radius, 1.0 / def.mass, def.restitution, def.friction};
  const auto [found, added] =
      material_index_.try_emplace(material, static_cast<std::uint32_t>(materials_.size()));
  if (added) materials_.push_back(Material{material[0], material[1], material[2], material[3]});
  material_.push_back(found->second);
  if (polyhedron) {
    polyhedra_ = true;
    shape_.push_back(shape);
    q0_.push_back(def.orientation.normalized());
    omega_.push_back(def.angular_velocity);
    spin_radius_.push_back(SpinRadiusOf(static_cast<std::uint32_t>(index)));
  }
  if (!def.envelope.IsZero() && !has_envelopes_) {
    has_envelopes_ = true;
    envelope_.resize(index);
  }
  if (has_envelopes_) envelope_.push_back(def.envelope);
  public_of_.push_back(static_cast<std::uint32_t>(index));
  internal_of_.push_back(static_cast<std::uint32_t>(index));
  queue_.Resize(index + 1);  // the element's slot and prediction
  const bool larger = radius > max_radius_;
  max_radius_ = std::max(max_radius_, radius);
  if (started_) {
    // A bigger body or the first envelope can change the broad phase, and the first body off
    // straight lines (a thrust of its own, an envelope, a polyhedron) ends the fast paths that
    // assume them: rebuild.
    if (larger || (has_envelopes_ && grid_) || (straight_lines_ && !StraightLines())) {
      Start();
    } else {
      const auto i = static_cast<std::uint32_t>(index);
      ShareStarts();  // starts_ may have moved
      if (grid_) grid_->Insert(i, def.position);
      if (all_pairs_) all_pairs_->Insert(i, def.position);
      SetReorderPeriod();
      PredictFull(i);
    }
  }
  return BodyId{static_cast<std::uint32_t>(index), 0};
}

void World::Impl::Start() {
  started_ = true;
  overlap_index_.Clear();
  const auto n = static_cast<std::uint32_t>(starts_.size());
  const Container& box = settings_.container;
  grid_.reset();
  all_pairs_.reset();
  queue_.Clear();
  queue_.ShrinkToFit();  // one slot per element, grown one by one by AddBody
  engagement_queue_.Clear();
  engagements_.Clear();
  // A restart (AddBody while running) predicts every element afresh below: the old predictions
  // go with the cleared queue, which holds no times for them (Reorder would carry them over).
  // The versions stay, as they count each body's path changes.
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::uint32_t version = PredictionOf(i).version;
    PredictionOf(i) = Prediction{};
    PredictionOf(i).version = version;
  }

  // Rebase every path at the current time so that cells and predictions start from now.
  for (std::uint32_t i = 0; i < n; ++i) {
    if (polyhedra_) q0_[i] = RigidPathOf(i).OrientationAt(now_).normalized();
    const Path path = PathOf(i).RebasedAt(now_);
    SetStart(i, PathStart{WrapIntoBox(path.p0), path.v0, path.t0});
  }

  straight_lines_ = StraightLines();
  // The batch pair test (TestGathered) while the elements' data fit in the caches: it trades
  // mispredicted branches for instructions, a gain when the data are at hand (N = 10^4: +30%
  // collisions per CPU s) and a loss when each pair waits for main memory, where the branching
  // walk lets the processor run ahead to more misses (N = 10^6: -7%; 10^5: even). See
  // docs/benchmarks.md, ninth measurement.
  batch_tests_ = straight_lines_ && n <= kBatchTestMaxElements;

  // The grid needs a box and bounded element radii (an envelope grows without bound).
  const bool boxed = box.kind != Container::Kind::kOpen;
  if (settings_.broadphase == Broadphase::kGrid && boxed && !has_envelopes_ && n > 0) {
    Grid::Config config;
    config.lo = box.lo;
    config.hi = box.hi;
    config.periodic = box.kind == Container::Kind::kPeriodicBox;
    config.min_cell_size = 2 * max_radius_;
    const Vec3 length = box.hi - box.lo;
    const double volume = length.prod();
    config.target_cell_size =
        std::cbrt(volume / (std::max(settings_.grid_cells_per_body, 1e-6) * n));
    if (Grid::Feasible(config)) grid_.emplace(config, n);
  }
  ShareStarts();
  if (!grid_) {
    AllPairs::Config config;
    config.lo = box.lo;
    config.hi = box.hi;
    config.periodic = box.kind == Container::Kind::kPeriodicBox;
    all_pairs_.emplace(config, n);
  }
  for (std::uint32_t i = 0; i < n; ++i) {
    if (grid_) grid_->Insert(i, starts_[i].p0);
    if (all_pairs_) all_pairs_->Insert(i, starts_[i].p0);
  }
  // The look-ahead (FetchAhead) once the per-element data outgrow the caches: at N = 10^6 +14%
  // collisions per CPU s, at 10^5 +14%, at 6x10^4 about +10%; at 3x10^4 -5% and at 10^4 -7%,
  // where the data are at hand anyway (docs/benchmarks.md, eleventh measurement).
  fetch_ahead_ = straight_lines_ && grid_ && n >= kFetchAheadMinElements;
  linear_finish_ =
      straight_lines_ && grid_ && settings_.container.kind != Container::Kind::kWalledBox;
  if (grid_) Reorder();  // start in spatial order
  events_since_reorder_ = 0;
  SetReorderPeriod();
  if (polyhedra_) EngageOverlappingAtStart();
  for (std::uint32_t i = 0; i < n; ++i) PredictFull(i);
}

BodyState World::Impl::StateAt(std::uint32_t i, double t) const {
  const Path& path = PathOf(i);
  BodyState state{
      WrapIntoBox(path.PositionAt(t)), path.VelocityAt(t), path.a, Radius(i), 1.0 / InvMass(i),
      PredictionOf(i).version};
  if (polyhedra_) {
    state.orientation = RigidPathOf(i).OrientationAt(t).normalized();
    state.angular_velocity = omega_[i];
  }
  return state;
}

double World::Impl::KineticEnergy() const {
  // Summed in public order: the result does not depend on the memory order (Reorder).
  double energy = 0;
  for (const std::uint32_t i : internal_of_) {
    energy += 0.5 / InvMass(i) * PathOf(i).VelocityAt(now_).squaredNorm();
    if (polyhedra_) {
      const Eigen::Matrix3d r = RigidPathOf(i).OrientationAt(now_).toRotationMatrix();
      const Vec3 w_B = r.transpose() * omega_[i];  // 1/2 w.I w in body axes
      energy += 0.5 / InvMass(i) * w_B.dot(ShapeOf(i).unit_inertia * w_B);
    }
  }
  return energy;
}

Vec3 World::Impl::AngularMomentum() const {
  Vec3 momentum = Vec3::Zero();
  for (const std::uint32_t i : internal_of_) {
    const Path path = PathOf(i);
    momentum += path.PositionAt(now_).cross(path.VelocityAt(now_)) / InvMass(i);
    if (polyhedra_) {
      const Eigen::Matrix3d r = RigidPathOf(i).OrientationAt(now_).toRotationMatrix();
      momentum += r * (ShapeOf(i).unit_inertia * (r.transpose() * omega_[i])) / InvMass(i);
    }
  }
  return momentum;
}

Vec3 World::Impl::Momentum() const {
  Vec3 momentum = Vec3::Zero();
  for (const std::uint32_t i : internal_of_) {
    momentum += PathOf(i).VelocityAt(now_) / InvMass(i);
  }
  return momentum;
}

Status World::Impl::Validate() const {
  if (polyhedra_) return ValidatePolyhedra();
  const auto n = static_cast<std::uint32_t>(starts_.size());
  const double tolerance = settings_.contact_tolerance;
  auto check_pair = [&](std::uint32_t i, std::uint32_t j) -> std::optional<Error> {
    const Vec3 d = MinimumImage(PathOf(j).PositionAt(now_) - PathOf(i).PositionAt(now_));
    const double reach = Radius(i) + Radius(j);
    const double gap = d.norm() - reach;
    if (gap < -tolerance * reach) {
      return Error{"bodies " + std::to_string(public_of_[i]) + " and " +
                   std::to_string(public_of_[j]) + " overlap by " + Format(-gap) +
                   " at t = " + Format(now_)};
    }
    return std::nullopt;
  };
  for (std::uint32_t i = 0; i < n; ++i) {
    if (grid_) {
      std::optional<Error> error;
      grid_->ForEachNeighbor(i, [&](std::uint32_t j, const Vec3&) {
        if (!error && j > i) error = check_pair(i, j);
      });
      if (error) return *error;
    } else {
      for (std::uint32_t j = i + 1; j < n; ++j) {
        if (std::optional<Error> error = check_pair(i, j)) return *error;
      }
    }
    if (settings_.container.kind == Container::Kind::kWalledBox) {
      const Vec3 p = PathOf(i).PositionAt(now_);
      for (int w = 0; w < 6; ++w) {
        const WallPlane plane = BoxWall(settings_.container, w);
        const double gap = plane.normal.dot(p) - plane.offset - Radius(i);
        if (gap < -tolerance * Radius(i)) {
          return Error{"body " + std::to_string(public_of_[i]) + " is " + Format(-gap) +
                       " beyond wall " + std::to_string(w) + " at t = " + Format(now_)};
        }
      }
    }
  }
  return Status::Ok();
}

std::size_t World::Impl::MemoryBytes() const {
  // A std::map node holds its value and about four pointers.
  std::size_t bytes =
      starts_.capacity() * sizeof(ElementStart) + acceleration_.capacity() * sizeof(Vec3) +
      held_by_.capacity() + free_acceleration_.capacity() * sizeof(Vec3) +
      materials_.capacity() * sizeof(Material) +
      material_index_.size() * (sizeof(std::array<double, 4>) + 40) +
      material_.capacity() * sizeof(std::uint32_t) + envelope_.capacity() * sizeof(Envelope) +
      (public_of_.capacity() + internal_of_.capacity()) * sizeof(std::uint32_t) +
      queue_.MemoryBytes() + engagement_queue_.MemoryBytes() +
      gathered_.capacity() * sizeof(std::uint32_t);
  bytes += shape_.capacity() * sizeof(std::uint32_t) + q0_.capacity() * sizeof(Eigen::Quaterniond) +
           omega_.capacity() * sizeof(Vec3) + spin_radius_.capacity() * sizeof(double);
  if (grid_) bytes += grid_->MemoryBytes();
  if (all_pairs_) bytes += all_pairs_->MemoryBytes();
  return bytes;
}

// --- World: thin forwarding to Impl ---

World::World(const WorldSettings& settings) : impl_(std::make_unique<Impl>(settings)) {}
World::~World() = default;
World::World(World&&) noexcept = default;
World& World::operator=(World&&) noexcept = default;

Result<BodyId> World::AddBody(const BodyDef& def) { return impl_->AddBody(def); }
Status World::AdvanceTo(double t) { return impl_->AdvanceTo(t); }
BodyState World::StateAt(BodyId id, double t) const {
  SPARSEDYN_ASSERT(IsValid(id), "StateAt: invalid BodyId");
  return impl_->StateAt(impl_->internal_of_[id.index], t);
}
double World::Time() const { return impl_->now_; }
std::size_t World::BodyCount() const { return impl_->starts_.size(); }
bool World::IsValid(BodyId id) const { return id.index < impl_->starts_.size(); }
BodyId World::IdOf(std::uint32_t index) const { return BodyId{index, 0}; }
void World::OnCollision(std::function<void(const CollisionEvent&)> callback) {
  impl_->on_collision_ = std::move(callback);
}
void World::OnSegment(std::function<void(const MotionSegment&)> callback) {
  impl_->on_segment_ = std::move(callback);
}
const Statistics& World::Stats() const { return impl_->stats_; }
const WorldSettings& World::Settings() const { return impl_->settings_; }
double World::KineticEnergy() const { return impl_->KineticEnergy(); }
Vec3 World::Momentum() const { return impl_->Momentum(); }
Vec3 World::AngularMomentum() const { return impl_->AngularMomentum(); }
double World::MaxPenetration() const { return impl_->max_penetration_; }
Status World::Validate() const { return impl_->Validate(); }
std::size_t World::MemoryBytes() const { return impl_->MemoryBytes(); }

std::uint64_t World::StateHash() const {
  // FNV-1a over the bytes of each value (little-endian integers and IEEE doubles).
  std::uint64_t hash = 0xcbf29ce484222325ull;
  const auto mix = [&hash](std::uint64_t bits) {
    for (int k = 0; k < 8; ++k) {
      hash ^= (bits >> (8 * k)) & 0xffu;
      hash *= 0x100000001b3ull;
    }
  };
  const auto mix_double = [&mix](double x) { mix(std::bit_cast<std::uint64_t>(x)); };
  const auto mix_vector = [&mix_double](const Vec3& v) {
    for (int k = 0; k < 3; ++k) mix_double(v[k]);
  };
  mix_double(Time());
  mix(BodyCount());
  for (std::uint32_t index = 0; index < BodyCount(); ++index) {
    const BodyState s = StateAt(IdOf(index), Time());
    mix_vector(s.position);
    mix_vector(s.velocity);
    mix_vector(s.acceleration);
    const Eigen::Vector4d q = s.orientation.coeffs();
    for (int k = 0; k < 4; ++k) mix_double(q[k]);
    mix_vector(s.angular_velocity);
    mix(s.version);
  }
  return hash;
}

}  // namespace sparsedyn
