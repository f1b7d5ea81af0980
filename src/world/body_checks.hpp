// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <optional>
#include <string>

#include "sparsedyn/result.hpp"
#include "sparsedyn/world.hpp"

namespace sparsedyn {

/// Checks the values of body definition `def` in isolation (every number finite and in range,
/// the orientation a unit quaternion): the error names "body <index>" and the field. Used by
/// World::AddBody and by the conventional method.
std::optional<Error> CheckBodyValues(const BodyDef& def, std::size_t index);

/// Checks drag coefficients: finite and >= 0; the error names the field as `name`.linear or
/// `name`.quadratic ("body 3: drag.linear must be ...", "settings.drag.quadratic ...").
std::optional<Error> CheckDrag(const Drag& drag, const std::string& name);

/// The drag body `def` moves under: its own, else the World's default `world_drag`; none for a
/// static body (it never moves) or a god object (it goes where its track drives it).
inline Drag DragOf(const BodyDef& def, const Drag& world_drag) {
  if (def.is_static || def.god) return Drag{};
  return def.drag.value_or(world_drag);
}

}  // namespace sparsedyn
