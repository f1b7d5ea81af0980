// SPDX-License-Identifier: MIT
#include "world/body_checks.hpp"

#include <cmath>
#include <string>
#include <utility>

#include "base/format.hpp"

namespace sparsedyn {

std::optional<Error> CheckBodyValues(const BodyDef& def, std::size_t index) {
  const std::string body = "body " + std::to_string(index) + ": ";
  if (!std::isfinite(def.radius) || def.radius <= 0) {
    return Error{body + "radius must be finite and > 0, got " + FormatExact(def.radius)};
  }
  if (!std::isfinite(def.mass) || def.mass <= 0) {
    return Error{body + "mass must be finite and > 0, got " + FormatExact(def.mass)};
  }
  if (!std::isfinite(def.restitution) || def.restitution < 0 || def.restitution > 1) {
    return Error{body + "restitution must be in [0, 1], got " + FormatExact(def.restitution)};
  }
  if (!std::isfinite(def.friction) || def.friction < 0) {
    return Error{body + "friction must be finite and >= 0, got " + FormatExact(def.friction)};
  }
  const Eigen::Vector4d q = def.orientation.coeffs();
  if (!q.allFinite() || std::abs(q.norm() - 1.0) > 1e-6) {
    return Error{body + "orientation must be a finite unit quaternion, got norm " +
                 FormatExact(q.norm())};
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
                     FormatExact(value[k])};
      }
    }
  }
  const double envelope[] = {def.envelope.e0, def.envelope.e1, def.envelope.e2};
  for (int k = 0; k < 3; ++k) {
    if (!std::isfinite(envelope[k]) || envelope[k] < 0) {
      return Error{body + "envelope.e" + std::to_string(k) + " must be finite and >= 0, got " +
                   FormatExact(envelope[k])};
    }
  }
  if (def.drag) {
    if (std::optional<Error> error = CheckDrag(*def.drag, body + "drag")) return *error;
  }
  return std::nullopt;
}

std::optional<Error> CheckDrag(const Drag& drag, const std::string& name) {
  // isfinite first: a NaN compared with < is an invalid operation (the tests trap it).
  for (const auto& [key, value] : {std::pair{"linear", drag.linear},
                                   std::pair{"quadratic", drag.quadratic}}) {
    if (!std::isfinite(value) || value < 0) {
      return Error{name + "." + key + " must be finite and >= 0, got " + FormatExact(value)};
    }
  }
  return std::nullopt;
}

}  // namespace sparsedyn
