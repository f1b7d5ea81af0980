// SPDX-License-Identifier: MIT
// Golden state hashes (Box2D's EXPECTED_HASH): fixed runs of the gas, the thesis preset and
// small worlds of every feature the World has (walls, gravity and wall holds, thrusts,
// envelopes, both broad phases) must end in exactly these states. A change of behaviour, however
// small, changes a hash; a refactoring must not. When a change of behaviour is intended, say so
// in the commit and put the new values here.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "scenes/gas.hpp"
#include "scenes/presets.hpp"
#include "scenes/random.hpp"
#include "sparsedyn/world.hpp"
#include "world/polyhedra_scene.hpp"

namespace sparsedyn {
namespace {

// Runs `world` to `until` and returns its hash (printed, so that new values can be read off).
// No capped loop may reach its cap in these runs (issue #39 part 6): not the World's (the walk)
// nor the process-wide ones (root narrowing, certification, impulse rounds, bisections).
std::uint64_t HashAfter(World& world, double until, const std::string& name) {
  ResetCapHits();
  EXPECT_TRUE(world.AdvanceTo(until));
  EXPECT_EQ(CapHits(), CapCounters{}) << "a capped loop reached its cap";
  EXPECT_EQ(world.Stats().walk_cap_hits, 0u);
  const std::uint64_t hash = world.StateHash();
  std::printf("%s: events %llu, collisions %llu, hash 0x%016llx\n", name.c_str(),
              static_cast<unsigned long long>(world.Stats().events),
              static_cast<unsigned long long>(world.Stats().collisions),
              static_cast<unsigned long long>(hash));
  return hash;
}

World Preset(const std::string& name, std::uint32_t n, double density, Broadphase broadphase) {
  scenes::PresetRequest request;
  request.name = name;
  request.n = n;
  request.density = density;
  request.seed = 7;
  request.broadphase = broadphase;
  Result<scenes::Preset> preset = scenes::MakePreset(request);
  EXPECT_TRUE(preset) << (preset ? "" : preset.error().message);
  return std::move(preset->world);
}

// Spheres of mixed radii, masses and restitutions dropped in a walled box under gravity (walls
// bounce them), some with thrusts of their own, optionally with envelopes (AllPairs). Lively
// enough (restitution near 1) that no pile forms: resting on each other is issue #37's.
World DroppedSpheres(Broadphase broadphase, bool envelopes) {
  WorldSettings settings;
  settings.container = Container::WalledBox(Vec3::Zero(), Vec3(8, 8, 8));
  settings.gravity = Vec3(0, 0, -9.81);
  settings.broadphase = broadphase;
  World world(settings);
  scenes::Random random(20261201);
  for (int i = 0; i < 48; ++i) {
    BodyDef def;
    def.radius = 0.2 + 0.2 * random.Uniform();
    def.position = Vec3(1 + (i % 4) * 2.0, 1 + (i / 4 % 4) * 2.0, 1 + (i / 16) * 1.8);
    def.velocity = scenes::DrawVector([&] { return random.Normal(); });
    def.mass = 0.5 + random.Uniform();
    def.restitution = 0.9 + 0.1 * random.Uniform();
    if (i % 7 == 3) {
      const double y = 0.5 * random.Normal();  // y before x: see scenes::DrawVector
      def.thrust = Vec3(0.5 * random.Normal(), y, 0);
    }
    if (envelopes && i % 5 == 1) def.envelope = Envelope{0.0, 0.01, 0.02};
    EXPECT_TRUE(world.AddBody(def));
  }
  return world;
}

TEST(StateHash, EqualStatesHashEqualAndAnyChangeShows) {
  World a = Preset("gas", 200, 0.2, Broadphase::kGrid);
  World b = Preset("gas", 200, 0.2, Broadphase::kGrid);
  EXPECT_EQ(a.StateHash(), b.StateHash());
  ASSERT_TRUE(a.AdvanceTo(1.0));
  ASSERT_TRUE(b.AdvanceTo(1.0));
  EXPECT_EQ(a.StateHash(), b.StateHash());
  ASSERT_TRUE(b.AdvanceTo(1.0 + 1e-12));  // the clock alone moved
  EXPECT_NE(a.StateHash(), b.StateHash());
}

TEST(StateHash, GasOnTheGrid) {
  World world = Preset("gas", 2000, 0.3, Broadphase::kGrid);
  EXPECT_EQ(HashAfter(world, 20.0, "gas grid"), 0xdd29c56d57328e4dull);
}

TEST(StateHash, GasOnAllPairs) {
  World world = Preset("gas", 200, 0.2, Broadphase::kAllPairs);
  EXPECT_EQ(HashAfter(world, 6.0, "gas allpairs"), 0xe92fbf162906509cull);
}

TEST(StateHash, ThesisPreset) {
  World world = Preset("thesis", 60, 0.05, Broadphase::kGrid);
  EXPECT_EQ(HashAfter(world, 10.0, "thesis grid"), 0x4dcdc055f2ef4a1aull);
}

TEST(StateHash, ThesisPresetOnAllPairs) {
  World world = Preset("thesis", 40, 0.1, Broadphase::kAllPairs);
  EXPECT_EQ(HashAfter(world, 6.0, "thesis allpairs"), 0x35d0d574779e15d4ull);
}

TEST(StateHash, DroppedSpheresOnTheGrid) {
  World world = DroppedSpheres(Broadphase::kGrid, /*envelopes=*/false);
  EXPECT_EQ(HashAfter(world, 10.0, "dropped grid"), 0x6e122ceaf7e8f836ull);
}

TEST(StateHash, DroppedSpheresWithEnvelopes) {
  World world = DroppedSpheres(Broadphase::kAllPairs, /*envelopes=*/true);
  EXPECT_EQ(HashAfter(world, 8.0, "dropped envelopes"), 0x963f643b4dbf0f59ull);
}

// Polyhedra of mixed shapes with friction and restitution below 1 in a walled box, with their
// own inertia tensors (RotationModel::kFullTensor).
TEST(StateHash, InelasticPolyhedraWithFriction) {
  testing::PolyhedraSceneOptions options;
  options.n = 27;
  options.seed = 5;
  options.restitution = 0.8;
  options.friction = 0.4;
  options.rotation_model = RotationModel::kFullTensor;
  World world = testing::MakePolyhedraWorld(options);
  EXPECT_EQ(HashAfter(world, 8.0, "polyhedra friction"), 0xb41f773d6756e4eeull);
}

}  // namespace
}  // namespace sparsedyn
