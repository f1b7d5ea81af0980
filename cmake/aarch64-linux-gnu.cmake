# SPDX-License-Identifier: MIT
# Cross build for 64-bit ARM with Debian's cross compiler (g++-aarch64-linux-gnu) against the
# arm64 multiarch libraries (libqhull-dev:arm64, libboost-dev:arm64, libgtest-dev:arm64;
# scripts/deps.sh --aarch64 installs them). Tests run under qemu-user: CTest and gtest_discover_tests go through the
# emulator. Used by scripts/aarch64.sh and .ci/run (docs/reliability.md).
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR aarch64)
set(CMAKE_C_COMPILER aarch64-linux-gnu-gcc)
set(CMAKE_CXX_COMPILER aarch64-linux-gnu-g++)
set(CMAKE_LIBRARY_ARCHITECTURE aarch64-linux-gnu)
set(CMAKE_FIND_ROOT_PATH /usr/aarch64-linux-gnu /usr)
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE BOTH)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE BOTH)
set(CMAKE_CROSSCOMPILING_EMULATOR qemu-aarch64;-L;/usr/aarch64-linux-gnu)
