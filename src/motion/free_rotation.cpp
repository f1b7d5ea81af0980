// SPDX-License-Identifier: MIT
#include "motion/free_rotation.hpp"

#include <algorithm>
#include <array>
#include <boost/math/policies/policy.hpp>
#include <boost/math/special_functions/ellint_rf.hpp>
#include <boost/math/special_functions/ellint_rj.hpp>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "base/format.hpp"
#include "motion/rigid_path.hpp"
#include "sparsedyn/assert.hpp"

namespace sparsedyn {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

// Boost.Math without exceptions (nothing in the step path throws; the arguments below are
// always in the functions' domains) and without promoting double to long double (the Carlson
// algorithms are accurate to a few ulps in double, at half the cost).
namespace bmp = boost::math::policies;
using EllipticPolicy =
    bmp::policy<bmp::promote_double<false>, bmp::domain_error<bmp::errno_on_error>,
                bmp::overflow_error<bmp::errno_on_error>,
                bmp::evaluation_error<bmp::errno_on_error>>;

double CarlsonRF(double x, double y, double z) {
  return boost::math::ellint_rf(x, y, z, EllipticPolicy());
}
double CarlsonRJ(double x, double y, double z, double p) {
  return boost::math::ellint_rj(x, y, z, p, EllipticPolicy());
}

// ∫_0^φ sin^2 / ((1 - n sin^2) Δ) dθ = (Π(n, φ | k) - F(φ | k)) / n, from sn = sin φ, cn = cos φ
// and dn = Δ(φ) (DLMF 19.25.14 with the F part taken out, so nothing cancels as n -> 0):
//   = sn^3 / 3 · R_J(cn^2, dn^2, 1, 1 - n sn^2).
// Taking the Jacobi values, not φ, keeps the digits of a small cn (φ near π/2, k near 1).
// `one_minus_n_sn2` is 1 - n sn^2, computed by the caller without cancellation.
double ThirdKindPart(double sn, double cn, double dn, double one_minus_n_sn2) {
  if (sn == 0.0) return 0.0;
  return sn * sn * sn / 3.0 * CarlsonRJ(cn * cn, dn * dn, 1.0, one_minus_n_sn2);
}

// The rotation taking body vectors to the momentum frame's coordinates, inverted: its columns
// are the momentum frame's axes in the body frame, e_x ∝ n × u, e_y = u × e_x, e_z = u, for
// the unit momentum u and the body axis n (never parallel to u: see InitElliptic).
Eigen::Quaterniond FrameFromMomentum(const Vec3& L_B, int axis_n) {
  const Vec3 u = L_B.normalized();
  const Vec3 x = Vec3::Unit(axis_n).cross(u).normalized();
  Eigen::Matrix3d columns;
  columns << x, u.cross(x), u;
  return Eigen::Quaterniond(columns);
}

// The power of 2 nearest below x > 0: dividing by it is exact.
double PowerOfTwoScale(double x) { return std::ldexp(1.0, std::ilogb(x)); }

std::string AxisName(int axis) { return std::string(1, static_cast<char>('x' + axis)); }

}  // namespace

double JacobiAmplitude(double u, double k, double kc) {
  if (u < 0.0) return -JacobiAmplitude(-u, k, kc);
  if (k == 0.0) return u;

  // The AGM of 1 and k': a_j, c_j = (a_{j-1} - b_{j-1}) / 2, and 1 - c_j / a_j = b_{j-1} / a_j.
  constexpr int kMaxSteps = 40;
  std::array<double, kMaxSteps + 1> a{}, c{}, b_before{};
  double an = 1.0, bn = kc;
  int steps = 0;
  while (steps < kMaxSteps) {
    const double next_c = 0.5 * (an - bn);
    const double next_a = 0.5 * (an + bn);
    ++steps;
    a[steps] = next_a;
    c[steps] = next_c;
    b_before[steps] = bn;
    bn = std::sqrt(an * bn);
    an = next_a;
    // Stopping at k_N = c_N / a_N <= 2^-27 leaves am(u_N | k_N) - u_N = O(k_N^2 u_N) <= ulps.
    if (next_c <= 0x1p-27 * next_a) break;
  }

  // φ_N = 2^N a_N u, then φ_{j-1} = (φ_j + asin((c_j / a_j) sin φ_j)) / 2 (DLMF 22.20.5). The
  // arcsine y = x sin φ comes near 1 for k near 1, where asin loses digits: take it as
  // atan2(y, sqrt((1 - y)(1 + y))) with 1 - y = (1 - x) + x (1 - sin φ), both terms >= 0.
  double phi = std::ldexp(a[static_cast<std::size_t>(steps)] * u, steps);
  for (int j = steps; j >= 1; --j) {
    const auto i = static_cast<std::size_t>(j);
    const double x = c[i] / a[i];
    const double y = x * std::sin(phi);
    if (std::abs(y) < 1e-3) {  // asin by its series, to round-off (the last terms ~ y^7)
      const double y2 = y * y;
      phi = 0.5 * (phi + y * (1.0 + y2 * (1.0 / 6.0 + y2 * (3.0 / 40.0))));
      continue;
    }
    double one_minus_y = 1.0 - y;
    if (y > 0.5) {
      const double half = 0.25 * std::numbers::pi - 0.5 * phi;
      one_minus_y = b_before[i] / a[i] + x * (2.0 * std::sin(half) * std::sin(half));
    }
    phi = 0.5 * (phi + std::atan2(y, std::sqrt(one_minus_y * (1.0 + y))));
  }
  return phi;
}

Result<FreeRotation> FreeRotation::Create(double t0, const Vec3& moments,
                                          const Eigen::Quaterniond& q_WB0, const Vec3& w_W0) {
  if (!std::isfinite(t0)) return Error{"FreeRotation: t0 must be finite, got " + FormatExact(t0)};
  for (int i = 0; i < 3; ++i) {
    if (!std::isfinite(moments[i]) || !(moments[i] > 0.0)) {
      return Error{"FreeRotation: the moment of inertia about body axis " + AxisName(i) +
                   " must be finite and > 0, got " + FormatExact(moments[i])};
    }
  }
  if (!q_WB0.coeffs().allFinite() || std::abs(q_WB0.norm() - 1.0) > kUnitTolerance) {
    return Error{"FreeRotation: the orientation must be a finite unit quaternion, got norm " +
                 FormatExact(q_WB0.norm())};
  }
  for (int i = 0; i < 3; ++i) {
    if (!std::isfinite(w_W0[i])) {
      return Error{"FreeRotation: the angular velocity's " + AxisName(i) +
                   " component must be finite, got " + FormatExact(w_W0[i])};
    }
  }
  return FreeRotation(t0, moments, q_WB0, w_W0);
}

FreeRotation::FreeRotation(double t0, const Vec3& moments, const Eigen::Quaterniond& q_WB0,
                           const Vec3& w_W0)
    : t0_(t0), moments_(moments), q0_(q_WB0), w_W0_(w_W0) {
  SPARSEDYN_ASSERT(std::isfinite(t0) && w_W0.allFinite(), "FreeRotation: t0 and ω finite");
  SPARSEDYN_ASSERT(moments.allFinite() && moments.minCoeff() > 0.0,
                   "FreeRotation: moments finite and > 0");
  SPARSEDYN_ASSERT(q_WB0.coeffs().allFinite() && std::abs(q_WB0.norm() - 1.0) <= kUnitTolerance,
                   "FreeRotation: q_WB0 a finite unit quaternion");
  // A quaternion already of norm 1 to the last bit is kept as it is (RigidPath's bits).
  if (q0_.squaredNorm() != 1.0) q0_.normalize();

  // The invariants, from the true moments.
  w_B0_ = q0_.conjugate() * w_W0_;
  L_W_ = q0_ * moments_.cwiseProduct(w_B0_).eval();
  energy_ = 0.5 * w_B0_.dot(moments_.cwiseProduct(w_B0_));
  max_omega_ = w_W0_.norm() * (1.0 + 4.0 * kEps);

  // Which closed form: the moments in increasing order, their spread relative to the largest.
  std::array<int, 3> order{0, 1, 2};
  std::sort(order.begin(), order.end(), [&](int i, int j) { return moments_[i] < moments_[j]; });
  const auto [lo, mid, hi] = order;
  const double scale = moments_[hi];
  const bool low_pair = moments_[mid] - moments_[lo] <= kNearlyEqualMoments * scale;
  const bool high_pair = moments_[hi] - moments_[mid] <= kNearlyEqualMoments * scale;
  const int zeros = static_cast<int>((w_B0_.array() == 0.0).count());
  if (zeros >= 2 || (low_pair && high_pair) ||
      moments_[hi] - moments_[lo] <= kNearlyEqualMoments * scale) {
    return;  // kConstant: ω = 0, about a principal axis, or a spherical top
  }
  if (low_pair) {
    InitAxisymmetric(w_B0_, hi, 0.5 * (moments_[lo] + moments_[mid]));
    return;
  }
  if (high_pair) {
    InitAxisymmetric(w_B0_, lo, 0.5 * (moments_[mid] + moments_[hi]));
    return;
  }

  // Elliptic: about the largest axis when |L|^2 > 2 E I_mid, else about the smallest. With
  // the moments normalised, d = σ (|L|^2 - 2 E I_mid) = I_c |I_c - I_b| ω_c^2 - I_a |I_b - I_a|
  // ω_a^2 (σ the sign of I_c - I_a) must be >= 0; the ω_b terms cancel exactly.
  const Vec3 i = moments_ / PowerOfTwoScale(scale);
  const Vec3 v = w_B0_ / PowerOfTwoScale(w_B0_.cwiseAbs().maxCoeff());
  const double about_hi =
      i[hi] * (i[hi] - i[mid]) * v[hi] * v[hi] - i[lo] * (i[mid] - i[lo]) * v[lo] * v[lo];
  if (about_hi >= 0.0) {
    InitElliptic(w_B0_, lo, mid, hi);
  } else {
    InitElliptic(w_B0_, hi, mid, lo);
  }
}

void FreeRotation::InitAxisymmetric(const Vec3& w_B, int axis, double pair_moment) {
  // Regular precession (Landau & Lifshitz §33): with I1 = I2, ω_B = L_B / I1 - Ω e3, the sum
  // of a turn about the world-fixed L at |L| / I1 and one about the body-fixed e3 at -Ω, so
  // q(t) = exp(L dt / I1) q0 exp(-Ω dt e3), and ω_B's part across e3 turns about e3 at Ω.
  kind_ = Kind::kAxisymmetric;
  axis_ = axis;
  Vec3 model = Vec3::Constant(pair_moment);
  model[axis] = moments_[axis];
  precession_ = (moments_[axis] - pair_moment) / pair_moment * w_B[axis];
  spin_W_ = q0_ * (model.cwiseProduct(w_B) / pair_moment).eval();
}

void FreeRotation::InitElliptic(const Vec3& w_B, int a, int b, int c) {
  kind_ = Kind::kElliptic;
  a_ = a;
  b_ = b;
  c_ = c;
  // Moments and ω scaled by powers of 2 (exactly) to about 1: no overflow or underflow in the
  // squares below, and an input exactly on the separatrix stays on it.
  const Vec3 i = moments_ / PowerOfTwoScale(moments_.maxCoeff());
  const double w_scale = PowerOfTwoScale(w_B.cwiseAbs().maxCoeff());
  const Vec3 v = w_B / w_scale;
  const double ia = i[a], ib = i[b], ic = i[c];
  const double va = v[a], vb = v[b], vc = v[c];
  const double dca = std::abs(ic - ia), dcb = std::abs(ic - ib), dba = std::abs(ib - ia);

  // With Δ = 2E and σ = sign(I_c - I_a), each as a sum of terms of one sign (no cancellation):
  // pa = σ(Δ I_c - L^2), pc = σ(L^2 - Δ I_a), d = σ(L^2 - Δ I_b) >= 0.
  const double pa = ia * dca * va * va + ib * dcb * vb * vb;
  const double pc = ib * dba * vb * vb + ic * dca * vc * vc;
  const double d = std::max(0.0, ic * dcb * vc * vc - ia * dba * va * va);

  // ω_a = A cn u, ω_b = B sn u, ω_c = C dn u, u = u0 + λ dt (van Zon & Schofield eq. 11-15,
  // here for both branches at once: a, b, c = smallest, middle, largest about the largest
  // axis, largest, middle, smallest about the smallest). k'^2 = 1 - k^2 has its own formula:
  // k'^2 = |I_c - I_a| d / (|I_c - I_b| pc), exactly 0 on the separatrix.
  m_ = dba * pa / (dcb * pc);
  mc_ = dca * d / (dcb * pc);
  kc_ = std::sqrt(mc_);
  lambda_ = w_scale * std::sqrt(pc * dcb / (ia * ib * ic));
  n_ = -ia * pa / (ic * pc);  // <= 0: Π never meets its pole
  const double amp_a = std::sqrt(pa / (ia * dca));
  const double amp_b = std::sqrt(pa / (ib * dcb));
  const double amp_c = std::sqrt(pc / (ic * dca));

  // Signs: ω_c keeps that of v_c; (ω_a, ω_b) -> (-ω_a, -ω_b) is a symmetry of Euler's
  // equations, so cn u0 >= 0 and |u0| <= K; Euler's equations then fix the sign of B given
  // the parity of the axis order (a, b, c).
  const double sigma = ic > ia ? 1.0 : -1.0;
  const double parity = (b - a + 3) % 3 == 1 ? 1.0 : -1.0;
  const double sign_c = vc >= 0.0 ? 1.0 : -1.0;
  const double sign_a = va >= 0.0 ? 1.0 : -1.0;
  const double sign_b = sign_a * sign_c * parity * sigma;  // of ω_b / sn, σ_a included
  amp_a_ = w_scale * sign_a * amp_a;
  amp_b_ = w_scale * sign_b * amp_b;
  amp_c_ = w_scale * sign_c * amp_c;

  // u0 from cn u0 = |v_a| / A and sn u0 = ±v_b / B (renormalised: E and L fix A and B only to
  // round-off), u0 = F(φ0) = sn R_F(cn^2, dn^2, 1) (DLMF 19.25.5), atanh(sn) when k = 1.
  double cn0 = std::abs(va) / amp_a;
  double sn0 = sign_b * vb / amp_b;
  const double h = std::hypot(cn0, sn0);
  cn0 /= h;
  sn0 /= h;
  const double dn0 = std::sqrt(mc_ + m_ * cn0 * cn0);
  if (mc_ == 0.0) {
    kind_ = Kind::kSeparatrix;
    quarter_ = kInfinity;
    u0_ = std::atanh(sn0);
  } else {
    quarter_ = CarlsonRF(0.0, mc_, 1.0);
    integral_quarter_ = CarlsonRJ(0.0, mc_, 1.0, 1.0 - n_) / 3.0;
    u0_ = sn0 * CarlsonRF(cn0 * cn0, dn0 * dn0, 1.0);
  }
  if (!std::isfinite(u0_)) {  // at the middle axis's equilibrium to round-off: ω constant
    kind_ = Kind::kConstant;
    return;
  }
  integral_u0_ = JacobiAt(u0_, true).integral;

  // The angle about L (Landau & Lifshitz §37, with the Euler angles' axis along e_a, which L
  // never reaches: |L_a| <= |L| sqrt(I_a (Δ I_c - L^2) / ((I_c - I_a) L^2)) < |L|):
  //   ψ' = L (Δ - I_a ω_a^2) / (L^2 - I_a^2 ω_a^2)
  //      = L / I_c + L (1/I_a - 1/I_c) (-n) sn^2 / (1 - n sn^2)
  //   ψ  = L dt / I_c + κ (∫(u) - ∫(u0)),  ∫(u) = ∫_0^u sn^2 / (1 - n sn^2) du,
  //   κ  = L (I_c - I_a) (Δ I_c - L^2) / (I_c^2 (L^2 - Δ I_a) λ).
  const double L_norm = i.cwiseProduct(v).norm();
  psi_rate_ = w_scale * L_norm / ic;
  psi_scale_ = L_norm * (ic - ia) * pa / (ic * ic * pc * (lambda_ / w_scale));
  frame_ = q0_ * FrameFromMomentum(moments_.cwiseProduct(w_B), a_);

  // |ω|^2 = A^2 (1 - s) + B^2 s + C^2 (1 - k^2 s) is linear in s = sn^2 in [0, 1].
  const double sharp = w_scale * std::sqrt(std::max(amp_a * amp_a + amp_c * amp_c,
                                                    amp_b * amp_b + amp_c * amp_c * mc_));
  const double i_min = moments_.minCoeff();
  const double by_energy = std::sqrt(2.0 * energy_ / i_min);
  const double by_momentum = L_W_.norm() / i_min;
  max_omega_ = std::min({sharp, by_energy, by_momentum}) * (1.0 + 16.0 * kEps);
}

FreeRotation::Jacobi FreeRotation::JacobiReduced(double r, bool integral) const {
  // |r| <= K/2: from the amplitude, where cn >= sqrt(k' / (1 + k')) keeps its digits.
  if (std::abs(r) <= 0.5 * quarter_) {
    const double phi = JacobiAmplitude(r, std::sqrt(m_), kc_);
    const double sn = std::sin(phi), cn = std::cos(phi);
    const double dn = std::sqrt(mc_ + m_ * cn * cn);
    if (!integral) return {sn, cn, dn, 0.0};
    return {sn, cn, dn, ThirdKindPart(sn, cn, dn, 1.0 - n_ * sn * sn)};
  }

  // Beyond, from v = r ∓ K (DLMF 22.4(iii)): sn(±K + v) = ±cd v, cn(±K + v) = ∓k' sd v,
  // dn(±K + v) = k' nd v, and sn^2(K + v) = cd^2 v turns the integrand into
  //   (1 / (1 - n)) (1 - (1 - n') sn^2 v / (1 - n' sn^2 v)),  1 - n' = k'^2 / (1 - n),
  // so ∫(±K + v) = ±∫(K) + (v - (1 - n') ∫'(v)) / (1 - n), ∫' with n' for n.
  const double side = r > 0.0 ? 1.0 : -1.0;
  const double vr = r - side * quarter_;
  const double phi = JacobiAmplitude(vr, std::sqrt(m_), kc_);
  const double s = std::sin(phi), c = std::cos(phi);
  const double d = std::sqrt(mc_ + m_ * c * c);
  if (!integral) return {side * c / d, -side * kc_ * s / d, kc_ / d, 0.0};
  const double weight = mc_ / (1.0 - n_);
  const double part = ThirdKindPart(s, c, d, c * c + weight * s * s);
  return {side * c / d, -side * kc_ * s / d, kc_ / d,
          side * integral_quarter_ + (vr - weight * part) / (1.0 - n_)};
}

FreeRotation::Jacobi FreeRotation::JacobiAt(double u, bool integral) const {
  if (kind_ == Kind::kSeparatrix) {
    // k = 1: sn = tanh u, cn = dn = sech u, and ∫ tanh^2 / (1 - n tanh^2) du =
    // (u - atan(ν tanh u) / ν) / (1 - n) with ν = sqrt(-n) (partial fractions in tanh u).
    const double t = std::tanh(u);
    const double e = std::exp(-std::abs(u));
    const double sech = 2.0 * e / (1.0 + e * e);
    const double nu = std::sqrt(-n_);
    const double z = nu * t;
    const double atan_over_nu = nu < 1e-8 ? t * (1.0 - z * z / 3.0) : std::atan(z) / nu;
    return {t, sech, sech, (u - atan_over_nu) / (1.0 - n_)};
  }
  // Quasi-periodicity: u = 2 K m + r with |r| <= K, am(u) = am(r) + m π, sn and cn change
  // sign with m, and ∫(u) = ∫(r) + 2 m ∫(K) (as Π(n, φ + mπ) = Π(n, φ) + 2 m Π(n)).
  const double periods = std::nearbyint(u / (2.0 * quarter_));
  Jacobi j = JacobiReduced(u - 2.0 * quarter_ * periods, integral);
  if (std::fmod(periods, 2.0) != 0.0) {
    j.sn = -j.sn;
    j.cn = -j.cn;
  }
  j.integral += 2.0 * periods * integral_quarter_;
  return j;
}

Vec3 FreeRotation::EllipticOmegaBody(const Jacobi& j) const {
  Vec3 w;
  w[a_] = amp_a_ * j.cn;
  w[b_] = amp_b_ * j.sn;
  w[c_] = amp_c_ * j.dn;
  return w;
}

Vec3 FreeRotation::OmegaBodyAt(double t) const {
  const double dt = t - t0_;
  switch (kind_) {
    case Kind::kConstant:
      return w_B0_;
    case Kind::kAxisymmetric: {
      // The part across e3 turns about e3 at Ω: ω'_1 = -Ω ω_2, ω'_2 = Ω ω_1 (Euler, I1 = I2).
      const int j1 = (axis_ + 1) % 3, j2 = (axis_ + 2) % 3;
      const double angle = precession_ * dt;
      const double co = std::cos(angle), si = std::sin(angle);
      Vec3 w = w_B0_;
      w[j1] = co * w_B0_[j1] - si * w_B0_[j2];
      w[j2] = si * w_B0_[j1] + co * w_B0_[j2];
      return w;
    }
    case Kind::kElliptic:
    case Kind::kSeparatrix:
      break;
  }
  return EllipticOmegaBody(JacobiAt(u0_ + lambda_ * dt, false));
}

Vec3 FreeRotation::OmegaWorldAt(double t) const {
  switch (kind_) {
    case Kind::kConstant:
      return w_W0_;
    case Kind::kAxisymmetric:
      return OrientationAt(t) * OmegaBodyAt(t);
    case Kind::kElliptic:
    case Kind::kSeparatrix:
      break;
  }
  const EllipticState state = EllipticAt(t - t0_);
  return state.q * state.w_B;
}

Eigen::Quaterniond FreeRotation::OrientationAt(double t) const {
  const double dt = t - t0_;
  switch (kind_) {
    case Kind::kConstant:
      // Exactly RigidPath::OrientationAt.
      if (w_W0_.x() == 0.0 && w_W0_.y() == 0.0 && w_W0_.z() == 0.0) return q0_;
      return RotationFromVector(w_W0_ * dt) * q0_;
    case Kind::kAxisymmetric:
      return RotationFromVector(spin_W_ * dt) * q0_ *
             RotationFromVector(Vec3::Unit(axis_) * (-precession_ * dt));
    case Kind::kElliptic:
    case Kind::kSeparatrix:
      break;
  }
  return EllipticAt(dt).q;
}

FreeRotation::EllipticState FreeRotation::EllipticAt(double dt) const {
  // q(t) = (q0 P(t0)^-1) R_z(ψ) P(t): P takes the body to the momentum frame (e_z along L).
  const Jacobi j = JacobiAt(u0_ + lambda_ * dt, true);
  const Vec3 w_B = EllipticOmegaBody(j);
  const double psi = psi_rate_ * dt + psi_scale_ * (j.integral - integral_u0_);
  const Eigen::Quaterniond about_z(std::cos(0.5 * psi), 0.0, 0.0, std::sin(0.5 * psi));
  const Eigen::Quaterniond q =
      frame_ * about_z * FrameFromMomentum(moments_.cwiseProduct(w_B), a_).conjugate();
  return {w_B, q.normalized()};
}

Vec3 FreeRotation::Amplitudes() const {
  Vec3 amplitudes = Vec3::Zero();
  if (kind_ != Kind::kElliptic && kind_ != Kind::kSeparatrix) return amplitudes;
  amplitudes[a_] = amp_a_;
  amplitudes[b_] = amp_b_;
  amplitudes[c_] = amp_c_;
  return amplitudes;
}

double FreeRotation::FlipPeriod() const {
  if (kind_ != Kind::kElliptic) return kInfinity;
  return 2.0 * quarter_ / lambda_;
}

}  // namespace sparsedyn
