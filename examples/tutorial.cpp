// SPDX-License-Identifier: MIT
// The C++ step of docs/tutorial.md: the billiards scene file run from C++.
//
//   example_tutorial   (from the repository root)
#include <cstdio>
#include <sparsedyn/io/scene_file.hpp>
#include <sparsedyn/world.hpp>

int main() {
  sparsedyn::Result<sparsedyn::SceneDescription> scene =
      sparsedyn::ReadScene("data/scenes/billiards.json");
  if (!scene) { std::fprintf(stderr, "%s\n", scene.error().message.c_str()); return 1; }
  sparsedyn::Result<sparsedyn::World> world = sparsedyn::BuildWorld(*scene);
  if (!world) { std::fprintf(stderr, "%s\n", world.error().message.c_str()); return 1; }

  world->OnCollision([](const sparsedyn::CollisionEvent& e) {
    std::printf("t = %.6f: body %u hits %s\n", e.time, e.a.index,
                e.b.valid() ? "a ball" : "a cushion");
  });
  if (sparsedyn::Status s = world->AdvanceTo(scene->duration); !s) {
    std::fprintf(stderr, "%s\n", s.error().message.c_str());
    return 1;
  }
  // Any body's state at any time from now on comes from its analytic path.
  sparsedyn::BodyState cue = world->StateAt(world->IdOf(0), world->Time());
  std::printf("cue ball at (%g, %g, %g)\n", cue.position.x(), cue.position.y(), cue.position.z());
}
