// SPDX-License-Identifier: MIT
#pragma once

// Independent references for the drag tests: the textbook closed form of linear drag in
// 128-bit floats (GCC's __float128, with its own exponential), the 1D closed forms of
// quadratic drag in long double, and a classical Runge-Kutta integrator in long double.
// None of them shares code or formulas with src/motion.

#include <array>
#include <cmath>

#include "sparsedyn/types.hpp"

namespace sparsedyn::testing {

using Quad = __float128;

/// ln 2 = sum_k 1 / (k 2^k), to 128-bit precision.
inline Quad QuadLn2() {
  static const Quad ln2 = [] {
    Quad sum = 0;
    Quad power = 1;
    for (int k = 1; k < 130; ++k) {
      power /= 2;
      sum += power / k;
    }
    return sum;
  }();
  return ln2;
}

/// e^x in 128-bit floats: x = k ln 2 + r with |r| <= ln 2 / 2, e^r by its Taylor series.
inline Quad QuadExp(Quad x) {
  const long k = std::lround(static_cast<double>(x / QuadLn2()));
  const Quad r = x - static_cast<Quad>(k) * QuadLn2();
  Quad term = 1;
  Quad sum = 1;
  for (int n = 1; n < 45; ++n) {
    term *= r / n;
    sum += term;
  }
  Quad scale = 1;
  const Quad two = k >= 0 ? Quad(2) : Quad(0.5);
  for (long i = 0; i < std::labs(k); ++i) scale *= two;
  return sum * scale;
}

/// The linear-drag motion x(dt) = x0 + v_inf dt + (v0 - v_inf)(1 - e^(-c1 dt)) / c1 with
/// v_inf = g / c1, velocity v_inf + (v0 - v_inf) e^(-c1 dt), in 128-bit floats (c1 > 0).
struct QuadState {
  std::array<Quad, 3> x, v, a;
};
inline QuadState TextbookLinearDrag(const Vec3& p0, const Vec3& v0, const Vec3& g, double c1,
                                    Quad dt) {
  QuadState s;
  const Quad decay = QuadExp(-static_cast<Quad>(c1) * dt);
  for (int i = 0; i < 3; ++i) {
    const Quad v_inf = static_cast<Quad>(g[i]) / c1;
    const Quad dv = static_cast<Quad>(v0[i]) - v_inf;
    s.x[i] = static_cast<Quad>(p0[i]) + v_inf * dt + dv * (1 - decay) / c1;
    s.v[i] = v_inf + dv * decay;
    s.a[i] = -static_cast<Quad>(c1) * dv * decay;
  }
  return s;
}

/// |q - x| for a 128-bit reference vector q and a double vector x.
inline double Distance(const std::array<Quad, 3>& q, const Vec3& x) {
  double sum = 0.0;
  for (int i = 0; i < 3; ++i) {
    const double d = static_cast<double>(q[i] - static_cast<Quad>(x[i]));
    sum += d * d;
  }
  return std::sqrt(sum);
}

/// Long-double state for the quadratic-drag references.
struct LongState {
  std::array<long double, 3> x, v;
};

/// |q - x| for long-double reference vectors.
inline double Distance(const std::array<long double, 3>& q, const Vec3& x) {
  long double sum = 0.0L;
  for (int i = 0; i < 3; ++i) {
    const long double d = q[i] - static_cast<long double>(x[i]);
    sum += d * d;
  }
  return static_cast<double>(std::sqrt(sum));
}

/// Classical fourth-order Runge-Kutta for x'' = g - c1 v - c2 |v| v in long double with
/// `steps` equal steps over [0, duration].
inline LongState ReferenceDragRk4(const Vec3& p0, const Vec3& v0, const Vec3& g, double c1,
                                  double c2, double duration, long steps) {
  using V = std::array<long double, 3>;
  auto accel = [&](const V& v) {
    const long double speed = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    V a;
    for (int i = 0; i < 3; ++i) a[i] = g[i] - c1 * v[i] - c2 * speed * v[i];
    return a;
  };
  auto axpy = [](const V& y, long double h, const V& d) {
    V r;
    for (int i = 0; i < 3; ++i) r[i] = y[i] + h * d[i];
    return r;
  };
  LongState s;
  for (int i = 0; i < 3; ++i) {
    s.x[i] = p0[i];
    s.v[i] = v0[i];
  }
  const long double h = static_cast<long double>(duration) / steps;
  for (long n = 0; n < steps; ++n) {
    const V k1v = accel(s.v), k1x = s.v;
    const V v2 = axpy(s.v, h / 2, k1v);
    const V k2v = accel(v2), k2x = v2;
    const V v3 = axpy(s.v, h / 2, k2v);
    const V k3v = accel(v3), k3x = v3;
    const V v4 = axpy(s.v, h, k3v);
    const V k4v = accel(v4), k4x = v4;
    for (int i = 0; i < 3; ++i) {
      s.x[i] += h / 6 * (k1x[i] + 2 * k2x[i] + 2 * k3x[i] + k4x[i]);
      s.v[i] += h / 6 * (k1v[i] + 2 * k2v[i] + 2 * k3v[i] + k4v[i]);
    }
  }
  return s;
}

/// The 1D closed forms of quadratic drag along +z with g = (0, 0, -gz), gz > 0, c1 = 0,
/// vertical velocity w0 (up > 0), at time t: going up, w' = -gz - c2 w^2 gives
/// w = vt tan(atan(w0 / vt) - k t) (vt = sqrt(gz / c2), k = sqrt(gz c2)) and
/// z = ln(cos(phi0 - k t) / cos(phi0)) / c2, until the apex t* = phi0 / k; falling,
/// w' = -gz + c2 w^2 gives w = -vt tanh(k (t - t*)) and z = z* - ln(cosh(k (t - t*))) / c2.
/// Returns {z, w}.
inline std::array<long double, 2> VerticalQuadraticDrag(double gz, double c2, double w0,
                                                        long double t) {
  const long double vt = std::sqrt(static_cast<long double>(gz) / c2);
  const long double k = std::sqrt(static_cast<long double>(gz) * c2);
  long double z_apex = 0.0L;
  long double t_apex = 0.0L;
  if (w0 > 0.0) {
    const long double phi0 = std::atan(w0 / vt);
    t_apex = phi0 / k;
    if (t < t_apex) {
      const long double phi = phi0 - k * t;
      return {std::log(std::cos(phi) / std::cos(phi0)) / c2, vt * std::tan(phi)};
    }
    z_apex = -std::log(std::cos(phi0)) / c2;
  } else {
    // Falling from w0 <= 0 with |w0| < vt: the same tanh curve, started at its time t_apex < 0.
    t_apex = -std::atanh(-w0 / vt) / k;
    z_apex = std::log(std::cosh(k * t_apex)) / c2;
  }
  const long double y = k * (t - t_apex);
  // ln cosh y = y + log1p(e^-2y) - ln 2 for y >= 0, without overflow.
  const long double log_cosh = y + std::log1p(std::exp(-2 * y)) - std::log(2.0L);
  return {z_apex - log_cosh / c2, -vt * std::tanh(y)};
}

}  // namespace sparsedyn::testing
