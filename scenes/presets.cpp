// SPDX-License-Identifier: MIT
#include "scenes/presets.hpp"

#include "scenes/gas.hpp"
#include "scenes/thesis.hpp"

namespace sparsedyn::scenes {
namespace {

constexpr double kGasDuration = 10.0;

Result<Preset> MakeGasPreset(const PresetRequest& request, std::uint32_t n, double density,
                             double duration) {
  GasOptions options;
  options.n = request.n.value_or(n);
  options.packing = request.density.value_or(density);
  options.seed = request.seed.value_or(1);
  Result<std::vector<BodyDef>> bodies = MakeGasBodies(options);
  if (!bodies) return bodies.error();

  // The scene lists every body, so that it can be written out and run again bit for bit.
  SceneDescription scene;
  scene.name = request.name;
  scene.seed = options.seed;
  scene.packing = options.packing;
  scene.duration = duration;
  scene.settings.broadphase = request.broadphase.value_or(Broadphase::kGrid);
  scene.settings.container =
      Container::PeriodicBox(Vec3::Zero(), Vec3::Constant(GasBoxSide(options)));
  const std::uint32_t sphere = scene.AddShape(SphereShape(options.radius));
  scene.bodies.reserve(bodies->size());
  for (const BodyDef& def : *bodies) {
    scene.bodies.push_back({.shape = sphere,
                            .position = def.position,
                            .velocity = def.velocity,
                            .mass = def.mass,
                            .restitution = def.restitution});
  }
  Result<World> world = BuildWorld(scene);
  if (!world) return world.error();
  return Preset{std::move(*world), std::move(scene), request.name, options.n,
                options.packing,   options.seed,     duration};
}

// The thesis scene (§7), also the embedded default scene of `sparsedyn run` (1000 polyhedra,
// 10 simulated seconds, a fraction of a second of work).
Result<Preset> MakeThesisPreset(const PresetRequest& request) {
  ThesisOptions options;
  options.n = request.n.value_or(options.n);
  options.packing = request.density.value_or(options.packing);
  options.seed = request.seed.value_or(options.seed);
  options.broadphase = request.broadphase.value_or(options.broadphase);
  Result<SceneDescription> scene = MakeThesisScene(options);
  if (!scene) return scene.error();
  scene->name = request.name;
  Result<World> world = BuildWorld(*scene);
  if (!world) return Error{"thesis: " + world.error().message};
  return Preset{std::move(*world), std::move(*scene), request.name,    options.n,
                options.packing,   options.seed,      options.duration};
}

}  // namespace

std::vector<std::string> PresetNames() { return {"default", "gas", "thesis"}; }

Result<Preset> MakePreset(const PresetRequest& request) {
  if (request.n && *request.n == 0) return Error{"--n must be >= 1"};
  if (request.name == "gas") return MakeGasPreset(request, 1000, 0.05, kGasDuration);
  if (request.name == "thesis" || request.name == "default") return MakeThesisPreset(request);
  std::string names;
  for (const std::string& name : PresetNames()) names += (names.empty() ? "" : ", ") + name;
  return Error{"unknown preset '" + request.name + "' (known: " + names + ")"};
}

}  // namespace sparsedyn::scenes
