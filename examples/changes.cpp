// SPDX-License-Identifier: MIT
// Changes during a run (the thesis's App. H.3 manipulations): build a World, run it, then, at
// the World's time, add a body, kick one, teleport one and remove one, and run on. Each change
// is checked and refused with a message, the World unchanged, when it cannot be made (here: a
// removed body's handle).
//
// Two balls move towards each other along x in a walled box, a cube and a third ball rest.
// At t = 1 ball A is kicked to 2 m/s, so that A and B meet at t = 1 + 3 / 3 = 2 instead of
// 2.5; the cube is kicked off its centre and spins; ball E is teleported; a fourth ball D is
// added. At t = 2.5 B is removed, and a kick of B is refused.
#include <cstdio>
#include <memory>

#include "sparsedyn/geometry/generators.hpp"
#include "sparsedyn/world.hpp"

namespace {

void Print(const char* name, const sparsedyn::BodyState& s) {
  std::printf(
      "  %s: position (%.6f, %.6f, %.6f), velocity (%.6f, %.6f, %.6f), "
      "angular velocity (%.6f, %.6f, %.6f)\n",
      name, s.position.x(), s.position.y(), s.position.z(), s.velocity.x(), s.velocity.y(),
      s.velocity.z(), s.angular_velocity.x(), s.angular_velocity.y(), s.angular_velocity.z());
}

// Whether a step that should work did; else prints the library's message.
bool Ok(const sparsedyn::Status& status) {
  if (!status) std::fprintf(stderr, "%s\n", status.error().message.c_str());
  return status.ok();
}

// The handle of an added body, or the message of its refusal and an invalid handle.
sparsedyn::BodyId Added(const sparsedyn::Result<sparsedyn::BodyId>& id) {
  if (id) return *id;
  std::fprintf(stderr, "%s\n", id.error().message.c_str());
  return {};
}

}  // namespace

int main() {
  using sparsedyn::Vec3;
  sparsedyn::World world({.container = sparsedyn::Container::WalledBox({0, 0, 0}, {10, 10, 10})});
  world.OnCollision([](const sparsedyn::CollisionEvent& e) {
    if (e.b.valid()) {
      std::printf("  collision at t = %.6f: body %u hits body %u, impulse %.6f N s\n", e.time,
                  e.a.index, e.b.index, e.impulse);
    } else {
      std::printf("  collision at t = %.6f: body %u hits wall %d\n", e.time, e.a.index, e.wall);
    }
  });

  // The bodies at t = 0: balls A and B, a cube C (half extents 0.5 m, 1 kg), ball E.
  sparsedyn::Result<sparsedyn::ConvexPolyhedron> box = sparsedyn::MakeBox(Vec3(0.5, 0.5, 0.5));
  if (!box) {
    std::fprintf(stderr, "%s\n", box.error().message.c_str());
    return 1;
  }
  const auto cube = std::make_shared<const sparsedyn::ConvexPolyhedron>(std::move(*box));
  const sparsedyn::BodyId a =
      Added(world.AddBody({.radius = 0.5, .position = {2, 5, 5}, .velocity = {1, 0, 0}}));
  const sparsedyn::BodyId b =
      Added(world.AddBody({.radius = 0.5, .position = {8, 5, 5}, .velocity = {-1, 0, 0}}));
  const sparsedyn::BodyId c = Added(world.AddBody({.shape = cube, .position = {5, 2, 5}}));
  const sparsedyn::BodyId e = Added(world.AddBody({.radius = 0.5, .position = {5, 5, 8}}));
  if (!a.valid() || !b.valid() || !c.valid() || !e.valid()) return 1;

  std::printf("run to t = 1\n");
  if (!Ok(world.AdvanceTo(1.0))) return 1;

  // Add a body now: it starts at the World's time.
  const sparsedyn::BodyId d =
      Added(world.AddBody({.radius = 0.5, .position = {5, 8, 5}, .velocity = {0, -1, 0}}));
  if (!d.valid()) return 1;
  std::printf("added ball D as body %u\n", d.index);

  // Kick A through its centre: its velocity changes by J / m, from 1 to 2 m/s.
  const Vec3 centre_a = world.StateAt(a, world.Time()).position;
  if (!Ok(world.ApplyImpulse(a, {1, 0, 0}, centre_a))) return 1;
  std::printf("kicked ball A through its centre\n");
  Print("A", world.StateAt(a, world.Time()));

  // Kick the cube at the middle of its +x face, upwards: dv = J / m = (0, 0, 1) m/s and
  // dw = I^-1 (r x J) = (0.5, 0, 0) x (0, 0, 1) / (1/6) = (0, -3, 0) rad/s (I = m (2 h^2) / 3).
  const Vec3 centre_c = world.StateAt(c, world.Time()).position;
  if (!Ok(world.ApplyImpulse(c, {0, 0, 1}, centre_c + Vec3(0.5, 0, 0)))) return 1;
  std::printf("kicked the cube off its centre\n");
  Print("C", world.StateAt(c, world.Time()));

  // Teleport E to another corner of the box.
  if (!Ok(world.SetPose(e, {8, 8, 8}, Eigen::Quaterniond::Identity()))) return 1;
  std::printf("teleported ball E\n");
  Print("E", world.StateAt(e, world.Time()));

  std::printf("run to t = 2.5\n");
  if (!Ok(world.AdvanceTo(2.5))) return 1;

  // Remove B; its handle is refused from then on.
  if (!Ok(world.RemoveBody(b))) return 1;
  std::printf("removed ball B: %zu bodies\n", world.BodyCount());
  if (sparsedyn::Status kick = world.ApplyImpulse(b, {1, 0, 0}, {0, 0, 0}); !kick) {
    std::printf("refused: %s\n", kick.error().message.c_str());
  }

  std::printf("run to t = 6\n");
  if (!Ok(world.AdvanceTo(6.0))) return 1;
  const struct {
    const char* name;
    sparsedyn::BodyId id;
  } named[] = {{"A", a}, {"B", b}, {"C", c}, {"D", d}, {"E", e}};
  for (const auto& [name, id] : named) {
    if (world.IsValid(id)) Print(name, world.StateAt(id, world.Time()));
  }
  const Vec3 p = world.Momentum();
  std::printf("momentum (%.6f, %.6f, %.6f), kinetic energy %.6f\n", p.x(), p.y(), p.z(),
              world.KineticEnergy());
  return 0;
}
