#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The soak (docs/reliability.md): long runs with World::Validate() every 10^4 events, printing
# energy and momentum drift and memory; fails when an invariant breaks, energy drifts or memory
# grows. Builds tests/soak's sparsedyn_soak in the release preset (optimized, asserts on).
#   scripts/soak.sh           the full soak: 10^8 gas collisions (N = 10^4), 10^7 polyhedron
#                             collisions (the thesis preset, 1000 bodies)
#   scripts/soak.sh --short   what CI runs: 10^6 and 10^5
# The settled pile kicked 10^4 times waits for resting contacts (issue #37): see the hook below.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"
gas=1e8
polyhedra=1e7
if [[ "${1:-}" == "--short" ]]; then
  gas=1e6
  polyhedra=1e5
fi
if [[ -z "${SPARSEDYN_SOAK_NO_BUILD:-}" ]]; then
  "$root/scripts/deps.sh"
  cmake --preset release >/dev/null
  cmake --build --preset release --target sparsedyn_soak -j"$(nproc)" >/dev/null
fi
soak=build/release/tests/soak/sparsedyn_soak
echo "soak: gas, $gas collisions"
"$soak" gas "$gas" 10000
echo "soak: thesis polyhedra, $polyhedra collisions"
"$soak" thesis "$polyhedra" 1000
# TODO(#37): a settled pile kicked 10^4 times, once resting contacts land ("$soak" pile ...).
