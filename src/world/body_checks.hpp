// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <optional>

#include "sparsedyn/result.hpp"
#include "sparsedyn/world.hpp"

namespace sparsedyn {

/// Checks the values of body definition `def` in isolation (every number finite and in range,
/// the orientation a unit quaternion): the error names "body <index>" and the field. Used by
/// World::AddBody and by the conventional method.
std::optional<Error> CheckBodyValues(const BodyDef& def, std::size_t index);

}  // namespace sparsedyn
