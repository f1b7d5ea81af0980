// SPDX-License-Identifier: MIT
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace sparsedyn {

// Selects and extrema of doubles that compile to conditional moves or min/max instructions,
// never to branches. GCC 12 turns `c ? a : b` and std::max on doubles into a compare and a
// jump, which the processor guesses wrong about half the time when the data decide it (which
// of two segment starts is later, whether a pair approaches); that costs more than the few
// instructions below. Each gives the same bits as the plain expression in its comment,
// signed zeros and NaNs included.

/// condition ? a : b
inline double Select(bool condition, double a, double b) {
  const std::uint64_t mask = std::uint64_t{0} - static_cast<std::uint64_t>(condition);
  return std::bit_cast<double>((std::bit_cast<std::uint64_t>(a) & mask) |
                               (std::bit_cast<std::uint64_t>(b) & ~mask));
}

/// condition ? a : b for pointers (GCC branches on `?:` here too).
template <typename T>
inline T* SelectPointer(bool condition, T* a, T* b) {
  const std::uintptr_t mask = std::uintptr_t{0} - static_cast<std::uintptr_t>(condition);
  return reinterpret_cast<T*>((reinterpret_cast<std::uintptr_t>(a) & mask) |
                              (reinterpret_cast<std::uintptr_t>(b) & ~mask));
}

/// condition ? x : 0 for an index (a valid index to read through when the condition fails).
inline std::uint32_t ZeroUnless(bool condition, std::uint32_t x) {
  return x & (std::uint32_t{0} - static_cast<std::uint32_t>(condition));
}

/// std::max(a, b), i.e. a < b ? b : a
inline double MaxOf(double a, double b) {
#if defined(__SSE2__)
  // maxsd x, y gives x > y ? x : y.
  return _mm_cvtsd_f64(_mm_max_sd(_mm_set_sd(b), _mm_set_sd(a)));
#else
  return Select(a < b, b, a);
#endif
}

/// a < b ? a : b (std::min(b, a): ties and NaN give b)
inline double MinOf(double a, double b) {
#if defined(__SSE2__)
  // minsd x, y gives x < y ? x : y.
  return _mm_cvtsd_f64(_mm_min_sd(_mm_set_sd(a), _mm_set_sd(b)));
#else
  return Select(a < b, a, b);
#endif
}

/// std::sqrt(x) for x >= 0 (the same correctly rounded result), without the library call that
/// GCC keeps beside the square-root instruction for a negative x (to set errno): a call on any
/// path of a loop makes it spill its registers around every iteration.
inline double SqrtOf(double x) {
#if defined(__SSE2__)
  const __m128d v = _mm_set_sd(x);
  return _mm_cvtsd_f64(_mm_sqrt_sd(v, v));
#else
  return std::sqrt(x);
#endif
}

/// std::round(q), the same bits, without the library call (baseline x86-64 has no rounding
/// instruction) when |q| < 1.5: a periodic box's minimum image divides a difference of two
/// positions in the box by its side, which gives 0 or +/-1 (a zero with q's sign, as
/// std::round gives it). Beyond that, and for NaN, the library.
inline double RoundNearOne(double q) {
  const double magnitude = std::abs(q);
  if (!(magnitude < 1.5)) return std::round(q);
  return std::copysign(Select(magnitude >= 0.5, 1.0, 0.0), q);
}

}  // namespace sparsedyn
