// SPDX-License-Identifier: MIT
#pragma once

#include <cmath>

#include "math/branchless.hpp"
#include "sparsedyn/world.hpp"
#include "world/body_store.hpp"
#include "world/box_walls.hpp"
#include "world/observers.hpp"

namespace sparsedyn {

/// What every part of the World reads: the settings, the container's geometry, the bodies and
/// the observers. The parts that act (the sparse phase, the detailed phase, the contact models,
/// the event loop) hold a reference to it and to the parts they call.
struct WorldCore {
  explicit WorldCore(const WorldSettings& world_settings)
      : settings(world_settings),
        periodic(world_settings.container.kind == Container::Kind::kPeriodicBox),
        period(periodic ? Vec3(world_settings.container.hi - world_settings.container.lo)
                        : Vec3::Zero()),
        bodies(world_settings) {}

  bool Walled() const { return settings.container.kind == Container::Kind::kWalledBox; }
  double Now() const { return bodies.paths.Now(); }

  /// The periodic image of offset d nearest to zero (d itself outside periodic boxes). Inline:
  /// a collision of a gas checks its pair's distance through it.
  Vec3 MinimumImage(Vec3 d) const {
    if (!periodic) return d;
    for (int k = 0; k < 3; ++k) d[k] -= period[k] * RoundNearOne(d[k] / period[k]);
    return d;
  }
  /// Position p wrapped into a periodic box (p itself in other containers).
  Vec3 WrapIntoBox(Vec3 p) const {
    if (!periodic) return p;
    const Vec3& lo = settings.container.lo;
    for (int k = 0; k < 3; ++k) p[k] -= period[k] * std::floor((p[k] - lo[k]) / period[k]);
    return p;
  }

  WorldSettings settings;
  bool periodic;
  Vec3 period;  // the periodic box's side lengths (zero outside periodic boxes)
  BodyStore bodies;
  Observers observers;
};

}  // namespace sparsedyn
