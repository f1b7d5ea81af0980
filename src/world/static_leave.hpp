// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "motion/path.hpp"
#include "world/body_store.hpp"

namespace sparsedyn {

/// When a centre of mass on the path `centre`, now inside the face polygon `loop` (world
/// frame, counter-clockwise seen from the side n points to) seen along n, first reaches one of
/// its edge lines: the exact root of the quadratic distance to each edge line, never late
/// (EarliestRoot, EventTime). now if it is on or outside the polygon already; kInfinity if it
/// never leaves.
double FaceLeaveTime(std::span<const Vec3> loop, const Vec3& n, const Path& centre, double now);

/// The loop of static s's face `face` in the world frame (counter-clockwise seen from outside).
std::vector<Vec3> StaticFaceLoop(const BodyStore& bodies, std::uint32_t s, std::int32_t face);

/// When body i, held on a static's face (Hold::on_static), leaves it: its centre of mass
/// crosses the face's boundary seen along the normal (docs/sparse-phase.md#coming-to-rest).
/// A polyhedron resting on its own face stays balanced until then (its centre of mass is over
/// its own face, which moves with it, and over the static's: over where they overlap). kInfinity
/// if no static holds i.
double StaticLeaveTime(const BodyStore& bodies, std::uint32_t i);

}  // namespace sparsedyn
