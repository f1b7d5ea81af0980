// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>

#include "sparsedyn/io/scene_file.hpp"
#include "sparsedyn/result.hpp"
#include "sparsedyn/world.hpp"

namespace sparsedyn::scenes {

/// The `thesis` preset (DESIGN.md, thesis §7): N convex polyhedra, each the hull of random points
/// with 24-600 faces, scaled to bounding radius 1 about its centroid, density 1, in a box with six
/// static walls sized so that the bounding spheres fill the fraction `packing`. Orientations are
/// uniform on SO(3); velocities are Maxwell-Boltzmann (isotropic Gaussian) with zero total
/// momentum, rescaled so that the mean speed is exactly `mean_speed`; spins have a uniform random
/// axis and a magnitude uniform in [0, max_spin]. Restitution 1, friction 0, no gravity.
///
/// Shapes come from a pool of `shape_pool` distinct random hulls (face counts uniform in
/// [min_faces, max_faces]), and each body draws one of them uniformly: ten thousand bodies then
/// build and store 128 hulls, not ten thousand, and each is a `random_convex` generator spec so
/// that the scene file stays small and reads back to the same shapes.
struct ThesisOptions {
  std::uint32_t n = 1000;  // the thesis's largest runs ("at 1000 objects", §7.1)
  double packing = 0.05;   // the thesis's constant 5% density (§7.0)
  std::uint64_t seed = 1;
  std::uint32_t shape_pool = 128;  // K; fewer when n is smaller
  int min_faces = 24;
  int max_faces = 600;
  double mean_speed = 1.0;  // m/s
  double max_spin = 1.0;    // rad/s
  double density = 1.0;     // kg/m^3
  double duration = 10.0;   // simulated seconds `sparsedyn run` advances by default
  Broadphase broadphase = Broadphase::kGrid;
};

/// The side of the cubic box [0, side]^3 whose volume the N unit bounding spheres fill to
/// `options.packing`.
double ThesisBoxSide(const ThesisOptions& options);

/// The scene, deterministic for the seed: every shape a generator spec, every body listed. Needs
/// no World, so it can be written out or given to another engine while BuildWorld refuses
/// polyhedra. Out-of-range options are an Error naming the option.
Result<SceneDescription> MakeThesisScene(const ThesisOptions& options);

}  // namespace sparsedyn::scenes
