// SPDX-License-Identifier: MIT
// Stands in for the generated viewer bundle when the build had no node/npm to make it:
// `sparsedyn view` then says what is missing (viewer/CMakeLists.txt).
#include "apps/cli/viewer_bundle.hpp"

namespace sparsedyn::cli {

ViewerBundle EmbeddedViewer() { return {}; }

}  // namespace sparsedyn::cli
