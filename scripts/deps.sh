#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Installs the Debian 12 packages the build needs, only those missing (apt-get, with sudo when
# not root): the compiler and libraries, the Python package's build tools (pybind11, numpy;
# pytest and matplotlib for its tests and examples) and Doxygen for the API reference; then the web viewer's npm packages (npm ci in viewer/, from its package-lock.json)
# when they are missing or older than the lock file. Run by scripts/run.sh, scripts/test.sh and
# .ci/run.
#   scripts/deps.sh            build + test dependencies
#   scripts/deps.sh --peers    also the peer engines for bench/peers (Bullet, FCL, libccd)
#   scripts/deps.sh --aarch64  also the cross build (scripts/aarch64.sh): the cross compiler,
#                              qemu-user and the arm64 multiarch Qhull, Boost and GoogleTest
set -euo pipefail

packages=(build-essential cmake pkg-config libeigen3-dev libqhull-dev libboost-dev libcli11-dev
          nlohmann-json3-dev libgtest-dev libgmock-dev libbenchmark-dev libassimp-dev
          libfcl-dev libccd-dev libbullet-dev libcgal-dev libgmp-dev libmpfr-dev
          libcpp-httplib-dev
          python3-dev python3-venv python3-pybind11 python3-numpy python3-pytest
          python3-matplotlib doxygen python3)
# clang for the sanitizer build and libFuzzer (the asan preset), valgrind for CI's memcheck.
packages+=(clang llvm valgrind)
if [[ "${1:-}" == "--peers" ]]; then
  packages+=(gnuplot-nox)
fi
aarch64=0
if [[ "${1:-}" == "--aarch64" ]]; then
  aarch64=1
  packages+=(g++-aarch64-linux-gnu qemu-user libqhull-dev:arm64 libboost-dev:arm64
            libgtest-dev:arm64)
fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
# The viewer's tools are looked for as commands: a node from elsewhere (which brings its own
# npm) must not be replaced by Debian's.
if ! command -v node >/dev/null || ! command -v npm >/dev/null; then
  missing+=(nodejs npm)
fi
if ! command -v chromium >/dev/null && ! command -v chromium-browser >/dev/null; then
  missing+=(chromium)
fi

if ((${#missing[@]} > 0)); then
  sudo_cmd=()
  if [[ $(id -u) -ne 0 ]]; then
    sudo_cmd=(sudo)
  fi
  echo "scripts/deps.sh: installing ${missing[*]}" >&2
  # The arm64 libraries come from the same archive as a second (multiarch) architecture.
  if ((aarch64)) && ! dpkg --print-foreign-architectures | grep -qx arm64; then
    "${sudo_cmd[@]}" dpkg --add-architecture arm64
  fi
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends \
    "${missing[@]}" >&2
fi

viewer=$(cd "$(dirname "${BASH_SOURCE[0]}")/../viewer" && pwd)
if [[ ! "$viewer/node_modules/.package-lock.json" -nt "$viewer/package-lock.json" ]]; then
  echo "scripts/deps.sh: npm ci in viewer/" >&2
  (cd "$viewer" && npm ci --no-audit --no-fund --loglevel=error >&2)
fi
