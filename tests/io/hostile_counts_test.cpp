// SPDX-License-Identifier: MIT
// A 100-byte file that declares 2^31 vertices (or triangles) must be refused without
// allocating from the declared count. This test binary replaces global operator new to
// record the largest single request made while a parser runs; every reader must stay far
// below what the declared count would need (2^31 * 24 bytes for the vertices alone).
#include <gtest/gtest.h>

#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <new>
#include <string>

#include "sparsedyn/io/mesh_io.hpp"

namespace {

std::atomic<bool> g_tracking{false};
std::atomic<std::size_t> g_largest_request{0};

void* Allocate(std::size_t size) {
  if (g_tracking.load(std::memory_order_relaxed)) {
    std::size_t seen = g_largest_request.load(std::memory_order_relaxed);
    while (size > seen && !g_largest_request.compare_exchange_weak(seen, size)) {
    }
  }
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}

}  // namespace

// Replacements of the global allocation functions (the unaligned ones; the aligned forms keep
// their default pair). The nothrow forms are replaced too: the standard library's defaults
// forward to operator new, but AddressSanitizer intercepts them separately, and memory it
// allocates must not reach the free() below (std::stable_sort's buffer in a World uses them).
void* operator new(std::size_t size) { return Allocate(size); }
void* operator new[](std::size_t size) { return Allocate(size); }
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  try {
    return Allocate(size);
  } catch (const std::bad_alloc&) {
    return nullptr;
  }
}
void* operator new[](std::size_t size, const std::nothrow_t& tag) noexcept {
  return operator new(size, tag);
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }

namespace sparsedyn {
namespace {

// Anything a 100-byte file legitimately needs (tokens, a few vertices, the error text) is
// tiny; a reserve from the declared count would ask for gigabytes.
constexpr std::size_t kLargestAllowedRequest = 4096;

std::string PadTo100Bytes(std::string text) {
  text.resize(100, ' ');
  return text;
}

struct Hostile {
  const char* label;
  MeshFormat format;
  std::string bytes;
  std::string expected_error;
};

std::vector<Hostile> HostileFiles() {
  std::string stl(100, '\0');
  stl.replace(0, 6, "binary");
  stl[83] = static_cast<char>(0x80);  // uint32 little endian 0x80000000 = 2^31 triangles
  return {
      {"OFF", MeshFormat::kOff,
       PadTo100Bytes("OFF\n2147483648 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"),
       "h.off:2: declares 2147483648 vertices, more than the remaining 81 bytes can hold"},
      {"Ohio", MeshFormat::kOhio, PadTo100Bytes("3 2147483648 3\n0 0 0\n1 0 0\n0 1 0\n3 1 2 3\n"),
       "h.ohio:1: declares 2147483648 faces, more than the remaining 85 bytes can hold"},
      {"PLY ascii", MeshFormat::kPly,
       PadTo100Bytes("ply\nformat ascii 1.0\nelement vertex 2147483648\nproperty float x\n"
                     "end_header\n"),
       "h.ply:3: declares 2147483648 'vertex' records, more than the remaining 25 bytes can hold"},
      {"PLY binary", MeshFormat::kPly,
       PadTo100Bytes("ply\nformat binary_little_endian 1.0\nelement vertex 2147483648\n"
                     "property double x\nend_header\n"),
       "h.ply:3: declares 2147483648 'vertex' records, more than the remaining 9 bytes can hold"},
      {"STL binary", MeshFormat::kStl, stl,
       "h.stl: byte 80: binary STL declares 2147483648 triangles (107374182484 bytes) but the "
       "file has 100 bytes"},
  };
}

TEST(HostileCounts, HundredByteFilesDeclaring2To31RecordsAreRefusedWithoutAllocating) {
  for (const Hostile& file : HostileFiles()) {
    SCOPED_TRACE(file.label);
    ASSERT_EQ(file.bytes.size(), 100u);
    const std::string name = file.expected_error.substr(0, file.expected_error.find(':'));
    g_largest_request = 0;
    g_tracking = true;
    Result<PolygonMesh> mesh = ParseMesh(file.bytes, file.format, name);
    g_tracking = false;
    ASSERT_FALSE(mesh);
    EXPECT_EQ(mesh.error().message, file.expected_error);
    EXPECT_LT(g_largest_request.load(), kLargestAllowedRequest);
  }
}

// The probe itself works: parsing a real file with a large vertex list is seen.
TEST(HostileCounts, AllocationProbeSeesLargeRequests) {
  std::string off = "OFF\n1000 0 0\n";
  for (int i = 0; i < 1000; ++i) off += "0 0 0\n";
  g_largest_request = 0;
  g_tracking = true;
  Result<PolygonMesh> mesh = ParseOff(off, "big.off");
  g_tracking = false;
  ASSERT_TRUE(mesh) << mesh.error().message;
  EXPECT_GE(g_largest_request.load(), 1000 * sizeof(Eigen::Vector3d));
}

}  // namespace
}  // namespace sparsedyn
