// SPDX-License-Identifier: MIT
#pragma once

#include <string>

namespace sparsedyn::cli {

/// The web viewer's page and script (viewer/, bundled by esbuild at build time).
struct ViewerBundle {
  std::string html;  ///< viewer.html; loads "viewer.js" and "recording.sdrec" beside it
  std::string js;    ///< viewer.js: the viewer with three.js, self-contained
};

/// The bundle compiled into this binary; both strings are empty when the build had no
/// node/npm to make it.
ViewerBundle EmbeddedViewer();

}  // namespace sparsedyn::cli
