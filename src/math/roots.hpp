// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <optional>

#include "math/polynomial.hpp"
#include "math/root_isolation.hpp"

namespace sparsedyn {

/// Real roots of a t^2 + b t + c = 0 in ascending order; returns how many (0, 1 or 2) were
/// written to `roots` (an out parameter). Numerically stable: the discriminant is formed in long
/// double and the roots as q / a and c / q with q = -(b + sign(b) sqrt(disc)) / 2, so neither
/// suffers cancellation. a == 0 drops to the linear root -c / b; a == b == 0 gives 0 roots (also
/// when c == 0, where every t solves it: callers that care must test that case themselves).
/// A double root (disc == 0) is reported twice. Roots beyond the double range are dropped.
int SolveQuadratic(double a, double b, double c, std::array<double, 2>& roots);

/// Real roots of the cubic p (coefficients low to high; a lower degree is fine), ascending,
/// each refined by certified Newton/bisection (IsolateRealRoots) to an adjacent pair of doubles,
/// of which the one with the smaller |p| is reported. Unlike SolveQuadratic, a multiple root is
/// reported once (at the middle of its uncertainty interval). Returns the count written.
int SolveCubic(const Polynomial& p, std::array<double, 3>& roots);

/// As SolveCubic, for a quartic (e.g. the meeting equation of two accelerating spheres, App. F.3).
int SolveQuartic(const Polynomial& p, std::array<double, 4>& roots);

/// The earliest root of p in [lo, hi] (lo <= hi, both finite; hi may be huge, e.g. 1e30).
/// Conservative: the result r satisfies lo <= r <= t*, where t* is the smallest real root in
/// [lo, hi] of the polynomial with exactly these double coefficients; even-multiplicity
/// (touching) roots count. Returns lo if p(lo) == 0 (or if |p(lo)| is within the evaluation
/// error bound), and lo for the zero polynomial. std::nullopt when p has no real root in
/// [lo, hi], except that a near-touch closer to 0 than the evaluation error (about 1e-18
/// relative to sum |c_i| |t|^i) is reported as a root, which is the conservative side.
/// Accuracy: simple roots to about one ulp (t* - r <= 1 ulp + u_ld * cond), double roots to
/// about sqrt(1e-18) relative. Bounded work (no hang) for any finite input; never NaN.
/// All degrees (0..8) go through certified isolation (IsolateRealRoots), with the closed-form
/// quadratic as Newton's starting point for degree 2; see docs/math.md.
std::optional<double> EarliestRoot(const Polynomial& p, double lo, double hi);

}  // namespace sparsedyn
