// SPDX-License-Identifier: MIT
// Placeholder translation unit; the presets land with the World (issue #2).
namespace sparsedyn::scenes {}
