// SPDX-License-Identifier: MIT
#pragma once

#include "sparsedyn/types.hpp"
#include "sparsedyn/world.hpp"

namespace sparsedyn {

/// A wall of a walled box: inward unit normal n and offset d (a point x is inside when
/// n.x >= d).
struct WallPlane {
  Vec3 normal;
  double offset;
};

/// Wall `wall` (0..5 = -x, +x, -y, +y, -z, +z) of `box`.
inline WallPlane BoxWall(const Container& box, int wall) {
  const int axis = wall / 2;
  Vec3 n = Vec3::Zero();
  if (wall % 2 == 0) {
    n[axis] = 1.0;  // the low wall: inside is x >= lo
    return {n, box.lo[axis]};
  }
  n[axis] = -1.0;  // the high wall: inside is -x >= -hi
  return {n, -box.hi[axis]};
}

}  // namespace sparsedyn
