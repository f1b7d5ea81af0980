// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>

namespace sparsedyn {

/// Division of 32-bit unsigned numbers by a divisor fixed in advance, by one 64x64 -> 128-bit
/// multiplication with ceil(2^64 / d) instead of an integer division (tens of cycles): exact for
/// every 32-bit numerator and divisor (Lemire, Kaser & Kurz, "Faster remainder by direct
/// computation", 2019). d = 1 has no 64-bit reciprocal and is kept apart.
class FastDivisor {
 public:
  FastDivisor() = default;
  explicit FastDivisor(std::uint32_t d) : d_(d), reciprocal_(d > 1 ? UINT64_MAX / d + 1 : 0) {}

  std::uint32_t Divisor() const { return d_; }

  /// n / d, rounded down.
  std::uint32_t Divide(std::uint32_t n) const {
    __extension__ using Wide = unsigned __int128;  // GCC's and Clang's 128-bit product
    const auto q = static_cast<std::uint32_t>((static_cast<Wide>(reciprocal_) * n) >> 64);
    return d_ == 1 ? n : q;
  }

  /// n mod d, from the fraction n / d's product keeps (Lemire, Kaser & Kurz's fastmod), exact
  /// as Divide, and without its test of d = 1 (a zero reciprocal: remainder 0), which GCC
  /// made a select at every fetch of the look-ahead.
  std::uint32_t Remainder(std::uint32_t n) const {
    __extension__ using Wide = unsigned __int128;
    const std::uint64_t fraction = reciprocal_ * n;
    return static_cast<std::uint32_t>((static_cast<Wide>(fraction) * d_) >> 64);
  }

 private:
  std::uint32_t d_ = 1;
  std::uint64_t reciprocal_ = 0;
};

}  // namespace sparsedyn
