// SPDX-License-Identifier: MIT
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

#include "sparse/mover.hpp"
#include "sparsedyn/types.hpp"

namespace sparsedyn {

/// Default prediction horizon (seconds after `now`): far beyond any run, finite for root finders.
inline constexpr double kPredictionHorizon = 1e30;

/// Earliest dt >= 0 at which the spheres of `a` and `b` (b displaced by `shift_b`, the periodic
/// image offset) touch: |dp(dt)| = Ra(dt) + Rb(dt) (App. F.1, F.3). kInfinity when they never
/// meet within `horizon`. Conservative: never later than the exact meeting of these paths.
/// Finite precision (Bannerman et al. 2014): spheres already touching or overlapping by round-off
/// meet now if approaching and are ignored while separating (the next real approach counts).
double PredictMeeting(const Mover& a, const Mover& b, const Vec3& shift_b,
                      double horizon = kPredictionHorizon);

/// Whether the gap of `a` and `b` is the straight-line quadratic (no relative acceleration, no
/// envelope growth), which PredictMeeting solves in closed form; else a quartic.
inline bool OnStraightLines(const Mover& a, const Mover& b) {
  return (b.a - a.a).isZero(0.0) && a.r1 + b.r1 == 0.0 && a.r2 + b.r2 == 0.0;
}

/// Whether the spheres of `a` and `b` (b displaced by `shift_b`) certainly stay apart for every
/// dt in [0, h]: their distance, overall and along each axis, is more than their paths and
/// radii can close in that time (|dv| h + |da| h^2 / 2 and the growth r1 h + r2 h^2 / 2, each
/// term at most its positive part). A few flops, for skipping PredictMeeting's root isolation
/// for pairs whose meeting, if any, comes after an event already found. False when it cannot
/// tell; the margin, a millionth of the sizes involved, dwarfs the rounding of these sums.
bool CertainlyApartWithin(const Mover& a, const Mover& b, const Vec3& shift_b, double h);

/// CertainlyApartWithin for one pair seen at several image shifts (AllPairs' 27 in a periodic
/// box): what does not depend on the shift (the relative velocity and acceleration and their
/// norms, the radii's growth rates) worked out once. The same numbers, so the same verdicts.
class ApartBound {
 public:
  ApartBound(const Mover& a, const Mover& b);
  bool Within(const Vec3& shift_b, double h) const;
  /// For every axis k and each of three shifts along it (`along[s][k]`, s = 0, 1, 2), apart[k][s]:
  /// whether Within(shift, h) holds by the test along k alone for every shift whose component
  /// there is along[s][k] and whose components' magnitudes are at most `largest_shift` (the
  /// margin taken at the largest size those images have). The summed radius and the margin are
  /// worked out once. All false when h is negative, infinite or NaN.
  using SlabVerdicts = std::array<std::array<bool, 3>, 3>;
  SlabVerdicts ApartAlongEach(const std::array<Vec3, 3>& along, const Vec3& largest_shift,
                              double h) const;

 private:
  Vec3 pa_, pb_, abs_sum_;  // the positions, and |pa| + |pb| per axis
  Vec3 abs_dv_, abs_da_;
  double speed_, acceleration_;  // |dv|, |da|
  double r0_, r1_, r2_;          // the summed radius and its growth rates (positive parts)
  // The summed radius at its largest over [0, h].
  double Reach(double h) const { return r0_ + (r1_ * h + 0.5 * r2_ * h * h); }
  // Within's margin for the images whose shifts are at most `largest_shift` in magnitude.
  double Size(const Vec3& largest_shift, double reach) const {
    return (abs_sum_ + largest_shift.cwiseAbs()).sum() + reach;
  }
  // The verdict along `axis` for the shift component `shift_along`, the reach and margin given.
  bool ApartAt(int axis, double shift_along, double reach, double size, double h) const {
    const double d = pb_[axis] + shift_along - pa_[axis];
    return Apart(std::abs(d), abs_dv_[axis], abs_da_[axis], reach, size, h);
  }
  // Within's test of one distance against what the paths and radii can close within h.
  static bool Apart(double distance, double speed, double acceleration, double reach, double size,
                    double h) {
    const double closing = speed * h + 0.5 * acceleration * h * h;
    return distance - reach - closing > 1e-6 * (size + closing);
  }
};

/// The 27 periodic images of a pair in order r = sx + 3 sy + 9 sz (x fastest, as AllPairs'
/// ImageShifts()), s being each axis's step (0, 1, 2 for -L, 0, +L): whether image r is apart by
/// the slab verdicts of its steps (apart[k][s], ApartBound::ApartAlongEach), along some axis.
inline bool ImageApart(const ApartBound::SlabVerdicts& apart, std::size_t r) {
  return apart[0][r % 3] || apart[1][r / 3 % 3] || apart[2][r / 9];
}

/// Whether ImageApart holds for each of the 26 images other than `nearest`, without visiting
/// them: the images it leaves are those whose step along every axis is not apart, so either
/// some axis has no such step, or along every axis only the nearest image's step may lack it.
inline bool OtherImagesApart(const ApartBound::SlabVerdicts& apart, std::size_t nearest) {
  const std::array<std::size_t, 3> steps = {nearest % 3, nearest / 3 % 3, nearest / 9};
  bool some_axis_apart = false, only_nearest_left = true;
  for (std::size_t k = 0; k < 3; ++k) {
    bool axis_apart = true;
    for (std::size_t s = 0; s < 3; ++s) {
      axis_apart &= apart[k][s];
      only_nearest_left &= s == steps[k] || apart[k][s];
    }
    some_axis_apart |= axis_apart;
  }
  return some_axis_apart || only_nearest_left;
}

/// Moves a double-precision meeting time `dt` > 0 of two spheres on straight lines back until
/// it is certainly not late (the gap is open and closing there): CertifyLinearInDoubles, or
/// for the pairs it leaves, the gap evaluated in long double with an error bound at steps back.
/// Out of line: reached only by pairs that do meet.
double CertifyLinearMeeting(const Vec3& pa, const Vec3& va, const Vec3& pb, const Vec3& vb,
                            const Vec3& shift_b, double reach, double dt);

/// CertifyLinearMeeting's first try, in doubles: one evaluation of the gap and its slope at dt
/// with rigorous rounding bounds, then a step back along the tangent (the gap is convex). The
/// certified time (dt itself when the gap is certainly open there), or -1 when the pair is not
/// certainly closing at dt (a graze) or the step would be long; the long-double loop then
/// decides.
double CertifyLinearInDoubles(const Vec3& pa, const Vec3& va, const Vec3& pb, const Vec3& vb,
                              const Vec3& shift_b, double reach, double dt);

/// The uncertified earliest meeting of two spheres on straight lines, from their relative
/// position dp and velocity dv, each as its (x, y) pair and z, and their summed radius, which
/// `reach()` returns and which is only asked for once the pair is found approaching (half the
/// pairs of a gas are not: their radii are never loaded). kInfinity, 0 (overlapping by
/// round-off and approaching) or the double-precision root, which FinishLinearMeeting then
/// certifies. The two early exits (separating; passing wide) come first, as most pairs of a
/// gas take one of them; x and y go in one SSE2 register, and every sum runs (x + y) + z as
/// Eigen's 3-vector dot products do (the same bits).
template <typename Reach>
inline double LinearMeetingRoot(const Eigen::Vector2d& dp_xy, double dp_z,
                                const Eigen::Vector2d& dv_xy, double dv_z, const Reach& reach) {
  const double b_half = dp_xy.dot(dv_xy) + dp_z * dv_z;
  if (b_half >= 0) return kInfinity;  // Not approaching: on straight lines, never again.
  const double r = reach();
  const double c = (dp_xy.squaredNorm() + dp_z * dp_z) - r * r;
  if (c <= 0) return 0.0;  // Overlapping by round-off and approaching: meet now.
  const double a_coef = dv_xy.squaredNorm() + dv_z * dv_z;
  const double disc = b_half * b_half - a_coef * c;
  if (disc < 0) return kInfinity;
  // Smaller root without cancellation: dt = C / (-B/2 + sqrt(disc)) (App. F.1).
  return c / (-b_half + std::sqrt(disc));
}

/// Whether LinearMeetingRoot finds a meeting (a finite root) for these values, without
/// branches: the same sums, so the same verdict, bit for bit. For batches of pairs whose
/// approach and miss are unpredictable (a gas): the few pairs that meet have their root
/// computed afterwards, while the test of the many that do not costs neither a square root nor
/// a branch that the processor guesses wrong about half the time.
inline bool LinearMeetingFound(const Eigen::Vector2d& dp_xy, double dp_z,
                               const Eigen::Vector2d& dv_xy, double dv_z, double reach) {
  const double b_half = dp_xy.dot(dv_xy) + dp_z * dv_z;
  const double c = (dp_xy.squaredNorm() + dp_z * dp_z) - reach * reach;
  const double a_coef = dv_xy.squaredNorm() + dv_z * dv_z;
  const double disc = b_half * b_half - a_coef * c;
  // disc >= 0 whenever c <= 0 (a_coef >= 0): an approaching overlap (root 0) is found too.
  return (b_half < 0) & (disc >= 0);
}

/// The end of PredictLinearMeeting: a root `dt` from LinearMeetingRoot, limited to `horizon`
/// and certified.
inline double FinishLinearMeeting(const Vec3& pa, const Vec3& va, const Vec3& pb, const Vec3& vb,
                                  const Vec3& shift_b, double reach, double dt,
                                  double horizon = kPredictionHorizon) {
  if (!(dt <= horizon)) return kInfinity;
  if (dt == 0.0) return 0.0;
  return CertifyLinearMeeting(pa, va, pb, vb, shift_b, reach, dt);
}

/// PredictMeeting for spheres of summed radius `reach` on straight lines (no acceleration, no
/// envelope) at positions pa, pb (+ shift_b, b's periodic image offset) with velocities va, vb.
/// Inline so that the two early exits cost a few flops. Bit-identical to PredictMeeting on the
/// same movers.
inline double PredictLinearMeeting(const Vec3& pa, const Vec3& va, const Vec3& pb, const Vec3& vb,
                                   const Vec3& shift_b, double reach,
                                   double horizon = kPredictionHorizon) {
  const Vec3 dp = pb + shift_b - pa;
  const Vec3 dv = vb - va;
  const double dt =
      LinearMeetingRoot(dp.head<2>(), dp[2], dv.head<2>(), dv[2], [reach] { return reach; });
  if (dt == kInfinity) return kInfinity;
  return FinishLinearMeeting(pa, va, pb, vb, shift_b, reach, dt, horizon);
}

/// Earliest dt >= 0 at which the sphere of `a` reaches the plane n.x = d from the side n.x > d
/// (n is the unit normal pointing into the allowed half-space), i.e. n.p(dt) - d = R(dt) while
/// approaching. Same conventions as PredictMeeting.
double PredictWallMeeting(const Mover& a, const Vec3& n, double d,
                          double horizon = kPredictionHorizon);

/// Earliest dt >= 0 at which the spheres of `a` and `b`, now overlapping, stop overlapping
/// (the end of an engagement, §3.3). kInfinity if they stay engaged within `horizon`.
/// Never earlier than the exact separation (an engagement must not end too soon).
double PredictSeparation(const Mover& a, const Mover& b, const Vec3& shift_b,
                         double horizon = kPredictionHorizon);

}  // namespace sparsedyn
