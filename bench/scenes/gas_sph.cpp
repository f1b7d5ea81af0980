// SPDX-License-Identifier: MIT
// Writes the `gas` preset's initial positions as a .sph snapshot (EDMD's input format: the
// count, the box sides, then "a x y z radius" per sphere), so that scripts/bench-edmd.sh runs
// Smallenburg's EDMD on the same spheres as gas_bench (EDMD draws its own velocities).
//   gas_sph N [PACKING [SEED]] > init.sph
#include <cstdio>
#include <cstdlib>
#include <string>

#include "scenes/gas.hpp"

int main(int argc, char** argv) {
  if (argc < 2 || argc > 4) {
    std::fprintf(stderr, "usage: %s N [PACKING [SEED]] > init.sph\n", argv[0]);
    return 2;
  }
  sparsedyn::scenes::GasOptions options;
  try {
    options.n = static_cast<std::uint32_t>(std::stoul(argv[1]));
    if (argc > 2) options.packing = std::stod(argv[2]);
    if (argc > 3) options.seed = std::stoull(argv[3]);
  } catch (const std::exception&) {
    std::fprintf(stderr, "%s: N, PACKING and SEED must be numbers\n", argv[0]);
    return 2;
  }
  const auto bodies = sparsedyn::scenes::MakeGasBodies(options);
  if (!bodies) {
    std::fprintf(stderr, "%s: %s\n", argv[0], bodies.error().message.c_str());
    return 1;
  }
  const double side = sparsedyn::scenes::GasBoxSide(options);
  std::printf("%zu\n%.17g %.17g %.17g\n", bodies->size(), side, side, side);
  for (const sparsedyn::BodyDef& body : *bodies) {
    std::printf("a %.17g %.17g %.17g %.17g\n", body.position.x(), body.position.y(),
                body.position.z(), options.radius);
  }
  return 0;
}
