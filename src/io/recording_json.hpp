// SPDX-License-Identifier: MIT
#pragma once

// The recording header as JSON (docs/recording-format.md "Header JSON"), shared by the writer,
// the reader and the JSON-lines export.

#include <nlohmann/json.hpp>
#include <string_view>

#include "sparsedyn/io/recording.hpp"

namespace sparsedyn::recording {

/// "open", "walled" or "periodic".
std::string_view ContainerKindName(Container::Kind kind);

/// [x, y, z].
nlohmann::json VectorJsonOf(const Vec3& v);

nlohmann::json HeaderToJson(const RecordingHeader& header);

/// The header from its JSON; unknown keys are ignored (the format allows minor additions).
/// An Error "<name>: header: <key>: <what>" on a missing key or a wrong type.
Result<RecordingHeader> HeaderFromJson(const nlohmann::json& json, std::string_view name);

}  // namespace sparsedyn::recording
