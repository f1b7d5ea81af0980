// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Geometry>
#include <cmath>
#include <cstdint>
#include <random>

namespace sparsedyn::scenes {

/// A vector of three draws, taken z first, then y, then x. Written as Vec3(draw(), draw(),
/// draw()) the order would be the compiler's: C++ leaves the order of function arguments
/// unspecified, and GCC on x86-64 took them right to left while GCC on aarch64 and clang took
/// them left to right, so the same seed gave other scenes there (docs/reliability.md). Sequenced
/// here in the order GCC on x86-64 used, so that the golden hashes stand.
template <typename Draw>
Eigen::Vector3d DrawVector(Draw&& draw) {
  const double z = draw();
  const double y = draw();
  const double x = draw();
  return {x, y, z};
}

/// A quaternion (w, x, y, z) of four draws, taken z, y, x, w (see DrawVector).
template <typename Draw>
Eigen::Quaterniond DrawQuaternion(Draw&& draw) {
  const double z = draw();
  const double y = draw();
  const double x = draw();
  const double w = draw();
  return Eigen::Quaterniond(w, x, y, z);
}

/// Portable random numbers for scenes: std::mt19937_64 (its output is fixed by the standard)
/// with our own mappings, because std::*_distribution differ between standard libraries and
/// the same seed must give the same scene everywhere.
class Random {
 public:
  explicit Random(std::uint64_t seed) : engine_(seed) {}

  /// Uniform in [0, 1) with 53 random bits.
  double Uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
  double Uniform(double lo, double hi) { return lo + (hi - lo) * Uniform(); }
  /// Uniform integer in [0, n).
  std::uint64_t Below(std::uint64_t n) { return engine_() % n; }

  /// Standard normal (Box-Muller; the second value is kept for the next call).
  double Normal() {
    if (has_spare_) {
      has_spare_ = false;
      return spare_;
    }
    double u = 0;
    while (u == 0) u = Uniform();
    const double v = Uniform();
    const double r = std::sqrt(-2.0 * std::log(u));
    spare_ = r * std::sin(2 * M_PI * v);
    has_spare_ = true;
    return r * std::cos(2 * M_PI * v);
  }

  std::mt19937_64& Engine() { return engine_; }

 private:
  std::mt19937_64 engine_;
  double spare_ = 0;
  bool has_spare_ = false;
};

}  // namespace sparsedyn::scenes
