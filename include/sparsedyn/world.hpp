// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include <Eigen/Geometry>

#include "sparsedyn/geometry/convex_polyhedron.hpp"
#include "sparsedyn/result.hpp"
#include "sparsedyn/statistics.hpp"
#include "sparsedyn/types.hpp"

namespace sparsedyn {

/// Which elements an actor is compared with when it predicts its next meeting.
enum class Broadphase {
  kAllPairs,  ///< every other element (the thesis, O(N) per prediction)
  kGrid,      ///< uniform cells with cell-crossing events (O(1) per event on average)
};

/// The space the bodies live in.
struct Container {
  /// Open space, a box with static walls, or a periodic box.
  enum class Kind { kOpen, kWalledBox, kPeriodicBox };
  /// Which of the three.
  Kind kind = Kind::kOpen;
  /// The box's lowest corner, m (unused in open space).
  Vec3 lo = Vec3::Zero();
  /// The box's highest corner, m (unused in open space).
  Vec3 hi = Vec3::Zero();

  /// Open space: no walls, no periodic images.
  static Container Open() { return {}; }
  /// A box with six static, immovable walls (restitution of the body applies).
  static Container WalledBox(const Vec3& lo, const Vec3& hi) { return {Kind::kWalledBox, lo, hi}; }
  /// A box with periodic boundaries (minimum-image convention).
  static Container PeriodicBox(const Vec3& lo, const Vec3& hi) {
    return {Kind::kPeriodicBox, lo, hi};
  }
};

/// How a polyhedron turns between events (docs/decisions/0003-rotation-model.md). Both keep the
/// world-frame angular velocity constant between events, which makes every path analytic.
enum class RotationModel {
  /// The body's inertia is the isotropic tensor with the polyhedron's trace (a mass distribution
  /// that turns like a sphere). Constant angular velocity is then its exact free motion: energy
  /// and angular momentum are conserved exactly, between events and through collisions.
  kSphericalTop,
  /// The polyhedron's own inertia tensor (uniform density) at every impulse. Constant angular
  /// velocity is then not the torque-free motion: between events the kinetic energy
  /// 1/2 w.I(t)w and the angular momentum I(t)w of a non-isotropic body vary with its
  /// orientation; collisions conserve both at the instant of impact.
  kFullTensor,
};

/// World-wide settings; plain data with defaults.
struct WorldSettings {
  /// Where the bodies live (open space by default).
  Container container;
  /// How each prediction finds its candidates.
  Broadphase broadphase = Broadphase::kGrid;
  Vec3 gravity = Vec3::Zero();  ///< m/s^2, applies to every body
  /// Bodies whose gap is below this fraction of their summed (bounding) radii touch: the contact
  /// tolerance.
  double contact_tolerance = 1e-9;
  /// How polyhedra turn (see RotationModel).
  RotationModel rotation_model = RotationModel::kSphericalTop;
  /// Collisions approaching slower than this (m/s) are elastic: the collapse guard.
  double elastic_below_speed = 1e-6;
  /// Grid cells per body (the cells are never smaller than the largest interaction distance).
  /// More cells mean fewer pair tests per prediction but more cell crossings; 6 is as fast as 4
  /// for the gas at N = 10^4 and a little faster at 10^5-10^6 and in the thesis scene of
  /// polyhedra, for 8 bytes more per body (measured 2026-11-26; the measurement log,
  /// docs/lab/measurements.md, has the runs).
  double grid_cells_per_body = 6.0;
  /// Abort AdvanceTo with an error when this many events pass without the clock advancing by
  /// more than a relative 1e-12 (inelastic collapse or a stuck configuration), or crawling on
  /// slow collisions (docs/sparse-phase.md): no hang. The window is short enough that a
  /// crawl of polyhedra (~10^5 events/s) is named within about a second.
  std::uint64_t stall_event_limit = 1u << 16;
  bool profile_phases = false;  ///< measure Statistics::seconds_* (costs two clock reads an event)
  /// The clock's value when the World is made, s: a World built from the state of another at
  /// time t (a final scene written by `sparsedyn run --write-final-scene`) runs on from t.
  double start_time = 0.0;
  /// The drag of every body whose BodyDef::drag is unset (App. H.2; zero: none). Coefficients
  /// finite and >= 0. Drag needs contact_tolerance >= kMinDragContactTolerance.
  Drag drag;
};

/// The smallest contact_tolerance a World with drag accepts: a contact on a body's true motion
/// is found by narrowing its envelope down to a fraction of the tolerance band (docs/dynamics.md,
/// "Drag in the World"), which needs a band wider than the true motion's certified error.
inline constexpr double kMinDragContactTolerance = 1e-12;

/// Checks `settings` (issue #39 part 9): a walled or periodic container with finite bounds of
/// magnitude <= 1e100 and hi > lo on every axis, known enumerators, finite gravity of magnitude
/// <= 1e100, contact_tolerance in [0, 0.1], elastic_below_speed in [0, 1e100],
/// grid_cells_per_body in (0, 1e6], stall_event_limit > 0 and start_time in [-1e12, 1e12].
/// The Error names the field ("settings.container.hi[2] = ..."). BuildWorld and the presets
/// return it; the World constructor asserts it.
Status ValidateSettings(const WorldSettings& settings);

/// A body: a sphere of `radius`, or the convex polyhedron `shape`.
struct BodyDef {
  double radius = 0.5;  ///< m; a sphere's radius (a polyhedron's is its bounding one)
  /// The polyhedron in its body frame, or null for a sphere. The World places it by its
  /// centroid: `position` is where the centroid goes. Shared between bodies of the same shape.
  std::shared_ptr<const ConvexPolyhedron> shape;
  Vec3 position = Vec3::Zero();        ///< centre of mass, m
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  ///< body to world, unit
  Vec3 velocity = Vec3::Zero();        ///< m/s
  Vec3 angular_velocity = Vec3::Zero();  ///< rad/s, world frame (polyhedra)
  Vec3 thrust = Vec3::Zero();          ///< acceleration of its own (App. F.3), added to gravity
  /// Later changes of `thrust`, times strictly increasing and not before the World's clock:
  /// each is an event of the body's.
  std::vector<ThrustChange> thrust_schedule;
  double mass = 1.0;                   ///< kg
  double restitution = 1.0;            ///< 1 = elastic; the collision uses the product of the two
  double friction = 0.0;               ///< Coulomb coefficient; a pair uses sqrt(mu_a mu_b)
  Envelope envelope;                   ///< growth of the bounding sphere beyond the body (App. F)
  /// Aerodynamic drag on the body (App. H.2): unset (std::nullopt) takes WorldSettings::drag,
  /// a value (Drag{} included) is the body's own. The body's true motion is then
  /// x'' = gravity + thrust - c1 v - c2 |v| v (docs/dynamics.md, "Drag in the World"). Spheres
  /// only, in Worlds without polyhedra or static bodies (not supported yet), and without an
  /// envelope of its own.
  std::optional<Drag> drag;
  /// A static body: fixed where it is placed, of infinite mass, with no events of its own (a
  /// floor, a table, a cushion). Any shape; velocity, spin, thrust and envelope must be zero.
  /// It may touch other bodies at the start, not overlap them, and may reach beyond a walled
  /// box's walls. Not in periodic boxes.
  bool is_static = false;
  /// A god object (App. H.3): driven along this track with bounded acceleration, from
  /// `position` and `velocity` now; of infinite mass to every other body (mass is ignored), not
  /// held by walls or statics, passing through other god objects. No thrust, spin or envelope;
  /// not in periodic boxes.
  std::optional<GodDef> god;
};

/// A body's state evaluated from its path at some time.
struct BodyState {
  /// Centre of mass, m.
  Vec3 position = Vec3::Zero();
  /// m/s.
  Vec3 velocity = Vec3::Zero();
  /// m/s^2 (gravity plus thrust, unless a wall holds the body).
  Vec3 acceleration = Vec3::Zero();
  double radius = 0.0;        ///< a sphere's radius or a polyhedron's bounding radius
  /// kg.
  double mass = 0.0;
  std::uint32_t version = 0;  ///< number of path changes (segments) so far
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  ///< body to world
  Vec3 angular_velocity = Vec3::Zero();  ///< rad/s, world frame
};

/// A resolved collision, reported to OnCollision callbacks.
struct CollisionEvent {
  /// When the bodies touched, s.
  double time = 0.0;
  /// The first body.
  BodyId a;
  BodyId b;              ///< invalid for a wall collision
  int wall = -1;         ///< 0..5 = -x,+x,-y,+y,-z,+z wall, or -1
  /// The contact point, world frame, m.
  Vec3 point = Vec3::Zero();
  Vec3 normal = Vec3::Zero();   ///< unit, from a towards b (towards the wall)
  double impulse = 0.0;         ///< N s along the normal
};

/// A new motion segment of one body: from `t0` on its centre follows
/// position + velocity (t - t0) + acceleration (t - t0)^2 / 2 and its orientation is
/// exp(angular_velocity (t - t0)) orientation, until its next segment. Reported to
/// OnSegment callbacks whenever a body's path changes (a collision); the first segment of every
/// body is its BodyDef at the time it was added. In a periodic box positions are not wrapped
/// into the box between segments: wrap them when drawing. For a body with drag the position
/// and velocity are its true state at t0 and the acceleration its true acceleration there: the
/// polynomial is the Taylor path its element follows, within max 0.1 of its radius of the true
/// motion (StateAt), with a new segment at each drag check.
struct MotionSegment {
  /// When the segment starts, s.
  double t0 = 0.0;
  /// Whose segment it is.
  BodyId body;
  /// The centre at t0, m.
  Vec3 position = Vec3::Zero();
  /// The velocity at t0, m/s.
  Vec3 velocity = Vec3::Zero();
  /// Constant over the segment, m/s^2.
  Vec3 acceleration = Vec3::Zero();
  std::uint32_t version = 0;  ///< the body's segment count after this change
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  ///< at t0, body to world
  Vec3 angular_velocity = Vec3::Zero();  ///< rad/s, world frame
};

/// Owns the bodies and runs the event loop: the sparse phase of the thesis (§3-§4) on the
/// bodies' spheres and, for polyhedra, the detailed phase of engaged pairs (§5.2,
/// docs/detailed-phase.md). Nothing is computed between events; a body's state at any time
/// comes from its path.
class World {
 public:
  /// An empty World at time 0 with these settings.
  explicit World(const WorldSettings& settings = {});
  ~World();
  /// Moves the whole World (its bodies, queue and callbacks).
  World(World&&) noexcept;
  /// Moves the whole World (its bodies, queue and callbacks).
  World& operator=(World&&) noexcept;
  World(const World&) = delete;
  World& operator=(const World&) = delete;

  /// Adds a body at the current time. Refused, with nothing changed, when a value is NaN/Inf,
  /// radius or mass <= 0, a magnitude is absurd (beyond 1e100, a radius below 2^-40 of its
  /// coordinates: src/world/hostile_values.hpp), restitution outside [0, 1], friction < 0, the
  /// orientation is not a unit quaternion, an envelope coefficient < 0, a drag coefficient is
  /// negative or not finite, drag would meet a polyhedron, a static body, a god object or an
  /// envelope (not supported yet), a thrust change is not later than the one before or comes
  /// before the clock, a god object's track is bad (ValidateGodTrack's fields, a time before
  /// the clock), the body lies outside the container, or it overlaps (polyhedra: touches) a
  /// body already present. Spheres and polyhedra may share a World.
  Result<BodyId> AddBody(const BodyDef& def);

  // --- Changes between AdvanceTo calls, at Time(). Each is checked first: a refused change
  // (an invalid or removed BodyId, a value NaN/Inf, a pose outside the container or touching
  // another body) changes nothing and names what was wrong. ---

  /// Removes the body; its handle is refused from then on (a later body may take its slot,
  /// under a new generation).
  Status RemoveBody(BodyId id);
  /// Sets the body's velocity (m/s), its angular velocity kept.
  Status SetVelocity(BodyId id, const Vec3& velocity);
  /// Sets the body's angular velocity (rad/s, world frame), its velocity kept.
  Status SetAngularVelocity(BodyId id, const Vec3& angular_velocity);
  /// Applies an impulse (N s, world frame) at a point (world frame): the velocity changes by
  /// impulse / m and the angular velocity by I^-1 ((point - centre) x impulse).
  Status ApplyImpulse(BodyId id, const Vec3& impulse, const Vec3& point);
  /// Moves the body to `position` with `orientation` at once (a teleport, App. H.3): its former
  /// partners predict again and the new place is searched. Refused where it would touch
  /// another body or leave the container.
  Status SetPose(BodyId id, const Vec3& position, const Eigen::Quaterniond& orientation);
  /// Sets the body's own acceleration (m/s^2, added to gravity) from now on, and its schedule
  /// of later changes (replacing what was left of the old one).
  Status SetThrust(BodyId id, const Vec3& thrust, const std::vector<ThrustChange>& schedule = {});
  /// Gives god object `id` a new maximum acceleration and track from now on (its targets not
  /// before Time()), planned from where it is and how it moves now. SetVelocity, ApplyImpulse,
  /// SetAngularVelocity and SetThrust refuse a god object; SetPose teleports it, and it goes on
  /// from there to the targets it had not reached.
  Status SetGodTrack(BodyId id, const GodDef& god);
  /// The part of god object `id`'s track not reached by Time() (and its maximum acceleration);
  /// none for another body.
  std::optional<GodDef> GodTrackOf(BodyId id) const;
  /// Whether `id` is a static body.
  bool IsStatic(BodyId id) const;
  /// Whether `id` is a god object.
  bool IsGod(BodyId id) const;

  /// Processes every event with time <= t, then sets the clock to t. Fails (clock at the last
  /// processed event) when the event loop stalls, see WorldSettings::stall_event_limit.
  Status AdvanceTo(double t);

  /// The state of `id` at time t >= Time() (or any t within its current segment).
  BodyState StateAt(BodyId id, double t) const;

  /// The clock: the time the World has advanced to, s.
  double Time() const;
  /// The number of bodies the World holds.
  std::size_t BodyCount() const;
  /// Whether `id` names a body the World holds (not removed).
  bool IsValid(BodyId id) const;
  /// Whether `id` is a convex polyhedron (BodyDef::shape), static, god object or moving; false
  /// for a sphere and for an invalid or removed handle.
  bool IsPolyhedron(BodyId id) const;
  /// The handle of the body in slot `index` (slots are numbered in the order bodies were
  /// added, and a removed body's slot is taken by a later one); invalid for an empty slot.
  /// Without removals, IdOf(0) ... IdOf(BodyCount() - 1) are all the bodies.
  BodyId IdOf(std::uint32_t index) const;
  /// The number of slots (BodyCount() plus the empty ones).
  std::size_t SlotCount() const;
  /// Every body's handle, in slot order.
  std::vector<BodyId> Bodies() const;

  /// Called after every resolved collision (body-body and body-wall), in event order.
  void OnCollision(std::function<void(const CollisionEvent&)> callback);
  /// Called after every change of a body's path (both bodies of a collision, in the order
  /// a, b, before the OnCollision call of that collision), in event order. With the
  /// StateAt of every body at the start, these segments reproduce every body's motion exactly.
  void OnSegment(std::function<void(const MotionSegment&)> callback);

  /// The event loop's counters so far.
  const Statistics& Stats() const;
  /// The settings the World was made with.
  const WorldSettings& Settings() const;

  double KineticEnergy() const;   ///< at Time(), translational + rotational
  Vec3 Momentum() const;          ///< at Time()
  Vec3 AngularMomentum() const;   ///< at Time(), about the world origin
  /// The deepest overlap of two bodies (or a body and a wall) seen at any processed event, m.
  double MaxPenetration() const;
  /// Checks at Time() that no two bodies overlap beyond the contact tolerance and that every
  /// body is inside the container (O(N^2) for small worlds, through the grid otherwise).
  Status Validate() const;
  /// Bytes of memory held by the World's data structures.
  std::size_t MemoryBytes() const;
  /// A 64-bit hash (FNV-1a) of the World's state: the clock, the body count and, in BodyId
  /// order, every body's StateAt(Time()) (position, velocity, acceleration, orientation,
  /// angular velocity, version) to the bit. Equal states give equal hashes on every build;
  /// golden values in tests pin the behaviour (tests/world/state_hash_test.cpp).
  std::uint64_t StateHash() const;

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

/// Refuses an end time `t` (a named Error) that is not finite or at which one step (ulp) of
/// the clock exceeds 2^-20 of the shortest time a body of `world` may take to move by its own
/// radius: past such a t consecutive events could not be told apart and AdvanceTo would stall.
/// The speed bound is all the kinetic energy in the lightest body plus what accelerations add
/// by t (in a walled box: a fall across its diagonal). O(N); `sparsedyn run` calls it before it
/// runs (docs/reliability.md).
Status CheckClockResolution(const World& world, double t);

}  // namespace sparsedyn
