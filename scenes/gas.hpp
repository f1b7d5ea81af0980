// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <vector>

#include "sparsedyn/result.hpp"
#include "sparsedyn/world.hpp"

namespace sparsedyn::scenes {

/// The `gas` preset (DESIGN.md): N hard spheres of radius 0.5 (diameter sigma = 1) and mass 1 in
/// a periodic cubic box sized for packing fraction `packing`, placed without overlap, with
/// Maxwell-Boltzmann velocities at temperature kT, zero total momentum, elastic, no gravity.
struct GasOptions {
  std::uint32_t n = 1000;
  double packing = 0.05;
  std::uint64_t seed = 1;
  double kT = 1.0;
  double radius = 0.5;
  double mass = 1.0;
  double restitution = 1.0;
  bool periodic = true;  // false: the same box with static walls
};

/// The box side that gives `options.packing` for `options.n` spheres.
double GasBoxSide(const GasOptions& options);

/// Positions (no two spheres overlap) and velocities of the gas, deterministic for the seed.
/// Low packings place at random (rejection with a cell list); packings above 0.25 start from a
/// random subset of a simple cubic lattice, which then melts within a few collision times.
Result<std::vector<BodyDef>> MakeGasBodies(const GasOptions& options);

/// A World holding the gas; `settings.container` is replaced by the gas box.
Result<World> MakeGas(const GasOptions& options, WorldSettings settings = {});

}  // namespace sparsedyn::scenes
