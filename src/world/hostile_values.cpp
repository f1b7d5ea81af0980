// SPDX-License-Identifier: MIT
#include "world/hostile_values.hpp"

#include "base/format.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace sparsedyn {

namespace {

const auto Format = FormatExact;

// "body 3: ", built only for an error (AddBody runs this for every body).
std::string Body(std::size_t index) { return "body " + std::to_string(index) + ": "; }

std::optional<Error> CheckAtMost(std::size_t index, const char* name, const Vec3& value) {
  for (int k = 0; k < 3; ++k) {
    if (std::abs(value[k]) > kMaxMagnitude) {
      return Error{Body(index) + name + "[" + std::to_string(k) + "] = " + Format(value[k]) +
                   " exceeds the largest magnitude the World takes (" + Format(kMaxMagnitude) +
                   ")"};
    }
  }
  return std::nullopt;
}

std::optional<Error> CheckInRange(std::size_t index, const char* name, double value) {
  if (value >= kMinMagnitude && value <= kMaxMagnitude) return std::nullopt;
  return Error{Body(index) + name + " = " + Format(value) + " is outside [" +
               Format(kMinMagnitude) + ", " + Format(kMaxMagnitude) +
               "], the range the World takes"};
}

}  // namespace

std::optional<Error> CheckHostileValues(const BodyDef& def, const WorldSettings& settings,
                                        std::size_t index) {
  const double radius = def.shape ? def.shape->bounding_radius() : def.radius;
  if (auto error = CheckInRange(index, def.shape ? "bounding radius" : "radius", radius)) {
    return error;
  }
  if (auto error = CheckInRange(index, "mass", def.mass)) return error;
  const Vec3 envelope(def.envelope.e0, def.envelope.e1, def.envelope.e2);
  const struct {
    const char* name;
    const Vec3& value;
  } vectors[] = {{"position", def.position},
                 {"velocity", def.velocity},
                 {"angular_velocity", def.angular_velocity},
                 {"thrust", def.thrust},
                 {"envelope", envelope}};
  for (const auto& [name, value] : vectors) {
    if (auto error = CheckAtMost(index, name, value)) return error;
  }

  // The sphere must be resolvable where it is: its radius against its own coordinates (and,
  // in a box, against the box's, which bound where it can go).
  double coordinate = def.position.cwiseAbs().maxCoeff();
  if (settings.container.kind != Container::Kind::kOpen) {
    coordinate = std::max({coordinate, settings.container.lo.cwiseAbs().maxCoeff(),
                           settings.container.hi.cwiseAbs().maxCoeff()});
  }
  if (radius < kMinRadiusPerCoordinate * coordinate) {
    return Error{Body(index) + "radius " + Format(radius) + " is below 2^-40 of its coordinates (" +
                 Format(coordinate) + "): its gaps would be lost in round-off"};
  }
  return std::nullopt;
}

Status CheckClockResolution(const World& world, double t) {
  if (!std::isfinite(t)) return Error{"end time must be finite, got " + Format(t)};
  if (world.BodyCount() == 0 || t <= world.Time()) return Status::Ok();

  // The fastest any body can move by t: all the kinetic energy in the lightest body (elastic
  // collisions only pass energy around), plus what its acceleration adds over the run (in a
  // walled box at most the energy of falling across the box's diagonal).
  double energy = 0, min_mass = kMaxMagnitude, min_radius = kMaxMagnitude, max_acceleration = 0;
  for (const BodyId id : world.Bodies()) {
    const BodyState s = world.StateAt(id, world.Time());
    if (!std::isfinite(s.mass)) continue;  // a static body never moves
    energy += 0.5 * s.mass * s.velocity.squaredNorm();
    min_mass = std::min(min_mass, s.mass);
    min_radius = std::min(min_radius, s.radius);
    max_acceleration = std::max(max_acceleration, s.acceleration.norm());
  }
  const Container& box = world.Settings().container;
  double speed = std::sqrt(2 * energy / min_mass);
  if (box.kind == Container::Kind::kWalledBox) {
    speed = std::sqrt(speed * speed + 2 * max_acceleration * (box.hi - box.lo).norm());
  } else {
    speed += max_acceleration * (t - world.Time());
  }
  if (speed == 0) return Status::Ok();
  const double crossing = min_radius / speed;
  const double ulp = std::abs(t - std::nextafter(t, 0.0));  // the step below t (no overflow)
  if (ulp <= kMaxClockUlpPerCrossing * crossing) return Status::Ok();
  return Error{"end time " + Format(t) + " s: one step of the clock there (" + Format(ulp) +
               " s) exceeds 2^-20 of the time the smallest body may take to move by its radius (" +
               Format(crossing) + " s); events could not be told apart"};
}

}  // namespace sparsedyn
