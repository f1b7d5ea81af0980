// SPDX-License-Identifier: MIT
// WorldSettings checked by the library (issue #39 part 9): every World builder (BuildWorld, the
// presets) calls ValidateSettings and the World constructor asserts it, so a bad container or
// tolerance is a named error, not a stalled or dividing-by-zero run.
#include <cmath>
#include <string>

#include "sparsedyn/world.hpp"
#include "base/format.hpp"
#include "world/body_checks.hpp"
#include "world/hostile_values.hpp"

namespace sparsedyn {
namespace {

const auto Format = FormatExact;

Status CheckNumber(const char* name, double value, double lo, double hi, bool lo_open) {
  // isfinite first: a NaN compared with > is an invalid operation (the tests trap it).
  if (std::isfinite(value) && (lo_open ? value > lo : value >= lo) && value <= hi) {
    return Status::Ok();
  }
  return Error{std::string("settings.") + name + " must be in " + (lo_open ? "(" : "[") +
               Format(lo) + ", " + Format(hi) + "], got " + Format(value)};
}

Status CheckContainer(const Container& box) {
  if (box.kind == Container::Kind::kOpen) return Status::Ok();
  if (box.kind != Container::Kind::kWalledBox && box.kind != Container::Kind::kPeriodicBox) {
    return Error{"settings.container.kind is not open, walled or periodic"};
  }
  for (int k = 0; k < 3; ++k) {
    const std::string axis = "[" + std::to_string(k) + "]";
    for (const auto& [name, value] : {std::pair{"lo", box.lo[k]}, std::pair{"hi", box.hi[k]}}) {
      if (!std::isfinite(value) || std::abs(value) > kMaxMagnitude) {
        return Error{std::string("settings.container.") + name + axis + " must be finite and at " +
                     "most " + Format(kMaxMagnitude) + " in magnitude, got " + Format(value)};
      }
    }
    if (!(box.hi[k] > box.lo[k])) {
      return Error{"settings.container.hi" + axis + " = " + Format(box.hi[k]) +
                   " must be greater than container.lo" + axis + " = " + Format(box.lo[k])};
    }
  }
  return Status::Ok();
}

}  // namespace

Status ValidateSettings(const WorldSettings& settings) {
  if (Status box = CheckContainer(settings.container); !box) return box;
  if (settings.broadphase != Broadphase::kAllPairs && settings.broadphase != Broadphase::kGrid) {
    return Error{"settings.broadphase is not allpairs or grid"};
  }
  if (settings.rotation_model != RotationModel::kSphericalTop &&
      settings.rotation_model != RotationModel::kFullTensor) {
    return Error{"settings.rotation_model is not spherical_top or full_tensor"};
  }
  for (int k = 0; k < 3; ++k) {
    const double g = settings.gravity[k];
    if (!std::isfinite(g) || std::abs(g) > kMaxMagnitude) {
      return Error{"settings.gravity[" + std::to_string(k) + "] must be finite and at most " +
                   Format(kMaxMagnitude) + " in magnitude, got " + Format(g)};
    }
  }
  // The contact tolerance is relative to summed radii: 0.1 is already a tenth of a body.
  if (Status s = CheckNumber("contact_tolerance", settings.contact_tolerance, 0, 0.1, false); !s) {
    return s;
  }
  if (Status s =
          CheckNumber("elastic_below_speed", settings.elastic_below_speed, 0, kMaxMagnitude, false);
      !s) {
    return s;
  }
  if (Status s = CheckNumber("grid_cells_per_body", settings.grid_cells_per_body, 0, 1e6, true);
      !s) {
    return s;
  }
  if (settings.stall_event_limit == 0) return Error{"settings.stall_event_limit must be > 0"};
  // The clock starts there: scene files allow [0, 1e12]; the library any finite time whose
  // magnitude leaves the clock a resolution (CheckClockResolution says more per World).
  if (Status s = CheckNumber("start_time", settings.start_time, -1e12, 1e12, false); !s) return s;
  if (std::optional<Error> error = CheckDrag(settings.drag, "settings.drag")) return *error;
  if (!settings.drag.IsZero() && settings.contact_tolerance < kMinDragContactTolerance) {
    // The message's 1e-12 is kMinDragContactTolerance.
    return Error{"settings.contact_tolerance must be >= 1e-12 with drag (its contacts are found "
                 "within the band), got " + Format(settings.contact_tolerance)};
  }
  return Status::Ok();
}

}  // namespace sparsedyn
