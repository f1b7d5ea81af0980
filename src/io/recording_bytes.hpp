// SPDX-License-Identifier: MIT
#pragma once

// Little-endian encoding of the recording's fixed-size fields (docs/recording-format.md),
// independent of the host's byte order.

#include <bit>
#include <cstdint>
#include <string>
#include <string_view>

#include "sparsedyn/types.hpp"

namespace sparsedyn::recording {

// Tags of the record stream.
inline constexpr std::uint8_t kTagSegment = 1;
inline constexpr std::uint8_t kTagCollision = 2;
inline constexpr std::uint8_t kTagEnd = 3;
// Segment flags.
inline constexpr std::uint8_t kSegmentHasAcceleration = 1;
inline constexpr std::uint8_t kSegmentHasRotation = 2;
// Collision flags.
inline constexpr std::uint8_t kCollisionWithWall = 1;

// Sizes in bytes, the figures of docs/recording-format.md.
inline constexpr std::size_t kBodyRecordBytes = 24;
inline constexpr std::size_t kSegmentBaseBytes = 1 + 1 + 4 + 8 + 6 * 8;        // 62
inline constexpr std::size_t kCollisionBytes = 1 + 1 + 4 + 4 + 8 + 6 * 8 + 8;  // 78
inline constexpr std::size_t kEndBytes = 1 + 8;
inline constexpr std::size_t kPreambleBytes = 8 + 4 + 4;  // magic, version, header_bytes

inline void PutU8(std::string& out, std::uint8_t v) { out.push_back(static_cast<char>(v)); }

inline void PutU32(std::string& out, std::uint32_t v) {
  for (int k = 0; k < 4; ++k) out.push_back(static_cast<char>((v >> (8 * k)) & 0xffu));
}

inline void PutF64(std::string& out, double v) {
  const auto bits = std::bit_cast<std::uint64_t>(v);
  for (int k = 0; k < 8; ++k) out.push_back(static_cast<char>((bits >> (8 * k)) & 0xffu));
}

inline void PutVec3(std::string& out, const Vec3& v) {
  for (int k = 0; k < 3; ++k) PutF64(out, v[k]);
}

// Reads fixed-size fields from a byte range; the caller checks Left() first.
class ByteCursor {
 public:
  explicit ByteCursor(std::string_view bytes) : bytes_(bytes) {}

  std::size_t Offset() const { return offset_; }
  std::size_t Left() const { return bytes_.size() - offset_; }
  std::string_view Take(std::size_t n) {
    const std::string_view s = bytes_.substr(offset_, n);
    offset_ += n;
    return s;
  }

  std::uint8_t U8() { return static_cast<std::uint8_t>(bytes_[offset_++]); }
  std::uint32_t U32() {
    std::uint32_t v = 0;
    for (int k = 0; k < 4; ++k) v |= static_cast<std::uint32_t>(U8()) << (8 * k);
    return v;
  }
  double F64() {
    std::uint64_t bits = 0;
    for (int k = 0; k < 8; ++k) bits |= static_cast<std::uint64_t>(U8()) << (8 * k);
    return std::bit_cast<double>(bits);
  }
  Vec3 Vector() {
    Vec3 v;
    for (int k = 0; k < 3; ++k) v[k] = F64();
    return v;
  }

 private:
  std::string_view bytes_;
  std::size_t offset_ = 0;
};

}  // namespace sparsedyn::recording
