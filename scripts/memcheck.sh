#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# valgrind memcheck of the CLI (docs/reliability.md): the default scene (1000 polyhedra, the
# first 0.2 simulated seconds: valgrind runs it ~50x slower) recorded, then the recording read
# back by export-jsonl and view --html. Any error, or a definite leak, fails. Uses the release
# build of scripts/test.sh (build/release/apps/cli/sparsedyn), building it when missing.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"
cli=build/release/apps/cli/sparsedyn
if [[ ! -x $cli ]]; then
  "$root/scripts/deps.sh"
  cmake --preset release >/dev/null
  cmake --build --preset release --target sparsedyn_cli -j"$(nproc)" >/dev/null
fi
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
memcheck=(valgrind --tool=memcheck --error-exitcode=99 --leak-check=full
          --errors-for-leak-kinds=definite --quiet)
until=${SPARSEDYN_MEMCHECK_UNTIL:-0.2}
"${memcheck[@]}" "$cli" run --until "$until" --record "$out/default.sdrec" --json > "$out/run.json"
"${memcheck[@]}" "$cli" export-jsonl "$out/default.sdrec" -o "$out/default.jsonl"
"${memcheck[@]}" "$cli" view "$out/default.sdrec" --html "$out/default.html"
echo "memcheck: 0 errors (run to t = $until: $(grep -o '"events": [0-9]*' "$out/run.json"),"\
     "$(wc -l < "$out/default.jsonl") JSON lines, $(wc -c < "$out/default.html") bytes of HTML)"
