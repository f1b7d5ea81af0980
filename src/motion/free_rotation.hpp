// SPDX-License-Identifier: MIT
#pragma once

// The exact torque-free rotation of a rigid body (issue #38 part 1), a closed form of time.
//
// How a segment would use it (part 2, not wired yet): at every event that changes a body's
// angular velocity, the World builds one FreeRotation from the body's principal moments, its
// orientation and its world-frame ω at the event time t0 (everything below is precomputed
// then), and keeps it beside the centre's Path. Between events the orientation and ω at any
// t are OrientationAt(t) and OmegaWorldAt(t), evaluated relative to t0; predictions bound the
// turning speed by MaxOmegaNorm(), which holds over the whole segment, as RigidPath's constant
// |ω| does today (docs/decisions/0003-rotation-model.md). The next event starts a new one.

#include <Eigen/Geometry>
#include <array>

#include "sparsedyn/result.hpp"
#include "sparsedyn/types.hpp"

namespace sparsedyn {

/// The free (torque-free) rotation of a rigid body from the orientation q_WB0 (body to world)
/// and world-frame angular velocity w_W0 it has at t0: Euler's equations I ω̇ = (I ω) × ω in
/// the body's principal frame, with the angular momentum L constant in the world frame.
/// Closed forms (van Zon & Schofield, J. Comput. Phys. 225 (2007) 145-164; Landau & Lifshitz,
/// Mechanics §37), each exact to round-off:
/// - kConstant: ω constant in the world frame, q(t) = exp(ω (t - t0)) q0, bit-identical to
///   RigidPath. A spherical top (all moments within kNearlyEqualMoments of each other), ω = 0,
///   and a rotation about a principal axis (two body components of ω exactly zero).
/// - kAxisymmetric: two moments within kNearlyEqualMoments (taken equal to their mean I1):
///   regular precession, q(t) = exp(L (t - t0) / I1) q0 exp(-Ω (t - t0) e3) in sines and
///   cosines, with Ω = (I3 - I1) ω3 / I1 about the symmetry axis e3.
/// - kElliptic: three distinct moments. ω(t) from Jacobi's sn, cn and dn, the orientation from
///   the incomplete elliptic integral of the third kind (in Carlson's symmetric forms).
/// - kSeparatrix: 2 E I_mid = |L|^2 exactly: the limit k = 1 (tanh and sech).
/// The model's ω, orientation, E and L are those of the moments it uses: in the nearly-equal
/// fall-backs they differ from the true ones by at most kNearlyEqualMoments relative.
///
/// Preconditions (asserted; Create() checks user input and reports an Error instead): moments
/// finite and > 0, q_WB0 finite with |q| within kUnitTolerance of 1 (then normalised), w_W0
/// finite. Evaluations are O(1) (no loops over time) and deterministic.
class FreeRotation {
 public:
  /// Which closed form the segment uses.
  enum class Kind { kConstant, kAxisymmetric, kElliptic, kSeparatrix };

  /// Moments whose difference is at most this fraction of the largest are taken as equal (the
  /// elliptic form divides by their difference). The fall-back's error grows like
  /// (ΔI / I) |ω|^2 (t - t0); the elliptic form just above the threshold agrees with a
  /// long-double RK4 to 2e-14 over 10 s at |ω| ~ 1, including when its rate λ ~ sqrt(ΔI / I)
  /// is small (tests/motion/free_rotation_test.cpp); at 1e-13 it was 6e-10 off.
  static constexpr double kNearlyEqualMoments = 1e-10;
  /// How far |q_WB0| may be from 1 (the World's own check on orientations).
  static constexpr double kUnitTolerance = 1e-6;

  /// The motion from time t0 (s) with principal moments `moments` (kg m^2, body axes x, y, z,
  /// any order), orientation q_WB0 (body to world) and angular velocity w_W0 (rad/s, world).
  FreeRotation(double t0, const Vec3& moments, const Eigen::Quaterniond& q_WB0, const Vec3& w_W0);

  /// The same, or an Error naming the bad field for user input (non-positive or non-finite
  /// moments, a non-finite or non-unit quaternion, a non-finite angular velocity).
  static Result<FreeRotation> Create(double t0, const Vec3& moments,
                                     const Eigen::Quaterniond& q_WB0, const Vec3& w_W0);

  /// The angular velocity at t in the body (principal) frame, rad/s.
  Vec3 OmegaBodyAt(double t) const;
  /// The angular velocity at t in the world frame, rad/s.
  Vec3 OmegaWorldAt(double t) const;
  /// The orientation at t (body to world), a unit quaternion. Its sign is not continuous in t.
  Eigen::Quaterniond OrientationAt(double t) const;

  /// The angular momentum in the world frame (kg m^2/s), constant.
  const Vec3& AngularMomentumWorld() const { return L_W_; }
  /// The rotational kinetic energy ½ ωᵀ I ω (J), constant.
  double Energy() const { return energy_; }
  /// A bound on |ω(t)| (rad/s) for every t: the sharp maximum of the closed form, never above
  /// sqrt(2 E / I_min) or |L| / I_min (plus a few ulps for round-off).
  double MaxOmegaNorm() const { return max_omega_; }

  double t0() const { return t0_; }
  /// The orientation at t0 (q_WB0, normalised).
  const Eigen::Quaterniond& q0() const { return q0_; }
  Kind kind() const { return kind_; }
  const Vec3& moments() const { return moments_; }

  /// The elliptic form's modulus k^2 and complement 1 - k^2 (0 and 1 for the other kinds).
  double ModulusSquared() const { return m_; }
  double ComplementSquared() const { return mc_; }
  /// The rate λ (rad/s) of the elliptic argument u = u0 + λ (t - t0) (0 for other kinds).
  double Rate() const { return lambda_; }
  /// K(k), the quarter period of sn in u (infinite at the separatrix, π/2 for other kinds).
  double QuarterPeriod() const { return quarter_; }
  /// The elliptic argument u0 + λ (t - t0) at t (0 for other kinds).
  double ArgumentAt(double t) const { return u0_ + lambda_ * (t - t0_); }
  /// The signed amplitudes in body axes: ω_B = (A cn u, B sn u, C dn u) on the body axes
  /// Axes() = (a, b, c), b the middle moment, c the axis the body turns about (zero for the
  /// kinds without elliptic functions).
  Vec3 Amplitudes() const;
  std::array<int, 3> Axes() const { return {a_, b_, c_}; }
  /// The time between two sign changes of the middle-axis component of ω, 2 K / λ (s):
  /// infinite at the separatrix and for the kinds without elliptic functions.
  double FlipPeriod() const;

 private:
  struct Jacobi {
    double sn, cn, dn;
    double integral;  // ∫_0^u sn^2 / (1 - n sn^2) du
  };
  void InitAxisymmetric(const Vec3& w_B, int axis, double pair_moment);
  void InitElliptic(const Vec3& w_B, int a, int b, int c);
  // sn, cn, dn at u, and the integral when `integral` (ω alone does not need it).
  Jacobi JacobiAt(double u, bool integral) const;
  Jacobi JacobiReduced(double r, bool integral) const;
  Vec3 EllipticOmegaBody(const Jacobi& j) const;
  struct EllipticState {
    Vec3 w_B;
    Eigen::Quaterniond q;
  };
  EllipticState EllipticAt(double dt) const;

  double t0_;
  Vec3 moments_;
  Eigen::Quaterniond q0_;
  Vec3 w_W0_;
  Vec3 L_W_;
  double energy_ = 0.0;
  double max_omega_ = 0.0;
  Kind kind_ = Kind::kConstant;

  // kAxisymmetric: the symmetry axis, ω(t0) in the body frame, the precession rate Ω, and the
  // world-frame rotation vector rate L / I1.
  int axis_ = 2;
  Vec3 w_B0_ = Vec3::Zero();
  double precession_ = 0.0;
  Vec3 spin_W_ = Vec3::Zero();

  // kElliptic, kSeparatrix: the body axes a, b (middle moment), c (rotation axis), the
  // amplitudes with their signs (ω_a = A cn, ω_b = B sn, ω_c = C dn), the modulus, the
  // characteristic n of Π, the argument u0 and rate λ, K(k), the integral at K, at u0, and the
  // angle's coefficients: ψ(t) = psi_rate_ (t - t0) + psi_scale_ (∫(u) - ∫(u0)).
  int a_ = 0, b_ = 1, c_ = 2;
  double amp_a_ = 0.0, amp_b_ = 0.0, amp_c_ = 0.0;
  double m_ = 0.0, mc_ = 1.0, kc_ = 1.0;
  double n_ = 0.0;
  double u0_ = 0.0, lambda_ = 0.0;
  double quarter_ = 1.5707963267948966;
  double integral_quarter_ = 0.0, integral_u0_ = 0.0;
  double psi_rate_ = 0.0, psi_scale_ = 0.0;
  Eigen::Quaterniond frame_ = Eigen::Quaterniond::Identity();  // q0 P(t0)^-1
};

/// The Jacobi amplitude am(u | k) for |u| <= K(k), given both k and k' = sqrt(1 - k^2)
/// (Boost's jacobi_elliptic takes k alone, which loses k' when k' is small). The arithmetic-
/// geometric mean (DLMF 22.20(ii)) with the arcsines near 1 evaluated from their complements.
double JacobiAmplitude(double u, double k, double kc);

}  // namespace sparsedyn
