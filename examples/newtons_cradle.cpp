// SPDX-License-Identifier: MIT
// In the spirit of the thesis's EXAMPLE2.C (App. M.1): build objects in code, move the
// simulation forward and follow their positions and velocities; react to each collision.
// Five equal balls in a row, almost touching; the first one swings in at 1 m/s. Elastic
// collisions of equal masses exchange velocities, so the motion runs down the row and the last
// ball leaves at 1 m/s while the others stop: a Newton's cradle without the strings.
#include <cstdio>
#include <vector>

#include "sparsedyn/world.hpp"

int main() {
  // Open space, no gravity; the balls are 1 mm apart, the first one 1 m away.
  sparsedyn::World world;
  std::vector<sparsedyn::BodyId> balls;
  for (int i = 0; i < 5; ++i) {
    const double x = i == 0 ? -1.0 : 1.0 + (i - 1) * 1.001;
    sparsedyn::BodyDef def;
    def.radius = 0.5;
    def.mass = 0.2;
    def.position = {x, 0, 0};
    def.velocity = {i == 0 ? 1.0 : 0.0, 0, 0};
    sparsedyn::Result<sparsedyn::BodyId> id = world.AddBody(def);
    if (!id) {
      std::fprintf(stderr, "%s\n", id.error().message.c_str());
      return 1;
    }
    balls.push_back(*id);
  }

  // React to each collision as it is resolved.
  world.OnCollision([](const sparsedyn::CollisionEvent& e) {
    std::printf("  collision at t = %.6f: ball %u hits ball %u, impulse %.6f N s\n", e.time,
                e.a.index, e.b.index, e.impulse);
  });

  // Step time forward and follow every ball.
  for (int step = 0; step <= 6; ++step) {
    const double t = 0.5 * step;
    if (sparsedyn::Status status = world.AdvanceTo(t); !status) {
      std::fprintf(stderr, "%s\n", status.error().message.c_str());
      return 1;
    }
    std::printf("t = %.1f\n", t);
    for (std::size_t i = 0; i < balls.size(); ++i) {
      const sparsedyn::BodyState s = world.StateAt(balls[i], t);
      std::printf("  ball %zu: x = %9.6f  vx = %9.6f\n", i, s.position.x(), s.velocity.x());
    }
  }
  const sparsedyn::Vec3 p = world.Momentum();
  std::printf("momentum (%.6f, %.6f, %.6f), kinetic energy %.6f\n", p.x(), p.y(), p.z(),
              world.KineticEnergy());
  return 0;
}
