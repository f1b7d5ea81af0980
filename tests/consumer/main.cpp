// SPDX-License-Identifier: MIT
// A user's first program against the installed package: two spheres meet head on.
#include <cmath>
#include <cstdio>

#include "sparsedyn/world.hpp"

int main() {
  sparsedyn::World world({.container = sparsedyn::Container::WalledBox({0, 0, 0}, {10, 10, 10})});
  auto a = world.AddBody({.radius = 0.5, .position = {2, 5, 5}, .velocity = {1, 0, 0}});
  auto b = world.AddBody({.radius = 0.5, .position = {8, 5, 5}, .velocity = {-1, 0, 0}});
  if (!a || !b) return 1;
  double first = -1;
  world.OnCollision([&](const sparsedyn::CollisionEvent& e) {
    if (first < 0) first = e.time;
  });
  if (!world.AdvanceTo(4.0)) return 1;
  // The gap of 5 m closes at 2 m/s: they touch at t = 2.5 s and swap velocities.
  const double v = world.StateAt(*a, 4.0).velocity.x();
  std::printf("consumer: linked sparsedyn, first collision at t = %.9f, v_a = %g\n", first, v);
  return std::abs(first - 2.5) < 1e-9 && std::abs(v + 1.0) < 1e-12 ? 0 : 1;
}
