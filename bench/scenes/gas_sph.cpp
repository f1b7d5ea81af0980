// SPDX-License-Identifier: MIT
// Writes the `gas` preset's initial positions as a .sph snapshot (EDMD's input format: the
// count, the box sides, then "a x y z radius" per sphere), so that scripts/bench-edmd.sh runs
// Smallenburg's EDMD on the same spheres as gas_bench (EDMD draws its own velocities).
//   gas_sph N [PACKING [SEED]] > init.sph
#include <charconv>
#include <cstdio>
#include <cstring>
#include <system_error>

#include "scenes/gas.hpp"

namespace {

// The whole of `text` as a number of type T (no sign on unsigned types, nothing after it).
template <typename T>
bool Parse(const char* text, T& value) {
  const char* end = text + std::strlen(text);
  const auto [stop, error] = std::from_chars(text, end, value);
  return error == std::errc() && stop == end && stop != text;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2 || argc > 4) {
    std::fprintf(stderr, "usage: %s N [PACKING [SEED]] > init.sph\n", argv[0]);
    return 2;
  }
  sparsedyn::scenes::GasOptions options;
  if (!Parse(argv[1], options.n) || (argc > 2 && !Parse(argv[2], options.packing)) ||
      (argc > 3 && !Parse(argv[3], options.seed))) {
    std::fprintf(stderr, "%s: N and SEED must be whole numbers >= 0, PACKING a number\n", argv[0]);
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
