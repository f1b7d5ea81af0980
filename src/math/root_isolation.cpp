// SPDX-License-Identifier: MIT
// Certified real-root isolation by the derivative cascade (docs/math.md#method): the roots of
// p' cut [lo, hi] into pieces on which p is monotone, so each piece holds at most one root, which
// a sign test at its ends detects. Applied from the highest derivative down, every level gets
// its critical points from the level above. Signs are only trusted when the extended-precision
// evaluation error bound certifies them; everything uncertain is reported as (part of) a root
// interval, which is what makes EarliestRoot conservative.
#include "math/root_isolation.hpp"

#include <algorithm>
#include <bit>
#include <climits>
#include <cmath>
#include <cstdint>
#include <limits>

#include "math/cap_counters.hpp"
#include "math/roots.hpp"
#include "sparsedyn/assert.hpp"

namespace sparsedyn {
namespace {

using Real = long double;
static_assert(std::numeric_limits<Real>::digits >= 64 &&
                  std::numeric_limits<Real>::max_exponent >= 16384,
              "root isolation needs x87 extended (or quad) long double: 11 more mantissa bits "
              "than double and an exponent range no degree-8 evaluation can leave");

constexpr int kCoefficientCount = kMaxPolynomialDegree + 1;
constexpr Real kUnitRoundoff = std::numeric_limits<Real>::epsilon() / 2;

// Horner's error is <= gamma_2d * sum |c_i| |t|^i with gamma_2d ~= 2 d u; doubling it covers the
// rounding of the computed sum |c_i| |t|^i itself (Higham 2002, Thm 5.3 and eq. 5.8).
constexpr Real kHornerErrorPerDegree = 4 * kUnitRoundoff;

// Relative margin on a Taylor enclosure radius for the rounding in its own computation
// (about 30 long double operations, each off by at most u).
constexpr Real kEnclosureMargin = 1 + 64 * kUnitRoundoff;

// Each bracket narrows at least twofold every two steps over the 2^64 doubles, so 128 steps
// always suffice; the cap only guards against a bug turning into a hang. Exhausting it keeps the
// bracket valid (its ends keep their certified classification), only wider.
constexpr int kMaxNarrowSteps = 256;

// Newton and secant candidates beyond this are dropped rather than rounded to double (half the
// double range: rounding to double cannot overflow from below it).
constexpr Real kNewtonRange = std::numeric_limits<double>::max() / 2;

// The largest ulp probe past a converged Newton iterate (see Narrow).
constexpr std::int64_t kMaxProbeUlps = std::int64_t{1} << 40;

// C(n, k) for n, k <= 8. At most 70 (7 bits), so C(i, k) * c_i is exact in a 64-bit mantissa.
constexpr std::array<std::array<int, kCoefficientCount>, kCoefficientCount> kBinomial = [] {
  std::array<std::array<int, kCoefficientCount>, kCoefficientCount> table{};
  for (int n = 0; n < kCoefficientCount; ++n) {
    table[static_cast<std::size_t>(n)][0] = 1;
    for (int k = 1; k <= n; ++k) {
      table[static_cast<std::size_t>(n)][static_cast<std::size_t>(k)] =
          table[static_cast<std::size_t>(n - 1)][static_cast<std::size_t>(k - 1)] +
          table[static_cast<std::size_t>(n - 1)][static_cast<std::size_t>(k)];
    }
  }
  return table;
}();

int Binomial(int n, int k) {
  return kBinomial[static_cast<std::size_t>(n)][static_cast<std::size_t>(k)];
}

// A point evaluation: value, its certified error bound and sign, and the slope for Newton.
struct Sample {
  Real value = 0;
  Real bound = 0;
  Real slope = 0;
  int sign = 0;
};

Sample EvaluateCoefficients(const Real* c, int degree, Real t) {
  Real value = c[degree];
  Real magnitude = std::fabs(value);
  Real slope = 0;
  const Real abs_t = std::fabs(t);
  for (int i = degree - 1; i >= 0; --i) {
    slope = slope * t + value;
    value = value * t + c[i];
    magnitude = magnitude * abs_t + std::fabs(c[i]);
  }
  Sample s;
  s.value = value;
  s.slope = slope;
  s.bound = kHornerErrorPerDegree * static_cast<Real>(degree) * magnitude;
  s.sign = value > s.bound ? 1 : (value < -s.bound ? -1 : 0);
  return s;
}

// The normalised derivatives q_j = p^(j) / j!, j = 0..n, with coefficients C(i + j, j) c_{i+j}:
// exact in long double (unlike p^(j), whose factors reach 8! = 40320). q_j' = (j + 1) q_{j+1},
// so the roots of q_{j+1} are the critical points of q_j and their signs agree.
class DerivativeTower {
 public:
  explicit DerivativeTower(const Polynomial& p) : degree_(p.Degree()) {
    for (int j = 0; j <= degree_; ++j) {
      for (int i = 0; i + j <= degree_; ++i) {
        q_[j][i] = static_cast<Real>(Binomial(i + j, j)) * static_cast<Real>(p.Coefficient(i + j));
      }
    }
  }

  Sample Evaluate(int level, Real t) const {
    return EvaluateCoefficients(q_[level], degree_ - level, t);
  }

  // The certified sign of q_level on all of [lo, hi] (0 if it may vanish there), from the exact
  // Taylor expansion about the midpoint m: q_j(m + s) = sum_k C(j + k, k) q_{j+k}(m) s^k.
  int EnclosureSign(int level, double lo, double hi) const {
    const Real m = (static_cast<Real>(lo) + static_cast<Real>(hi)) / 2;
    const Real h = std::max(m - lo, hi - m) * kEnclosureMargin;
    const Sample center = Evaluate(level, m);
    Real radius = center.bound;
    Real h_power = 1;
    for (int k = 1; level + k <= degree_; ++k) {
      h_power *= h;
      const Sample term = Evaluate(level + k, m);
      radius += static_cast<Real>(Binomial(level + k, k)) * (std::fabs(term.value) + term.bound) *
                h_power;
    }
    radius *= kEnclosureMargin;
    return center.value > radius ? 1 : (center.value < -radius ? -1 : 0);
  }

 private:
  int degree_;
  Real q_[kCoefficientCount][kCoefficientCount];  // only q_[j][0 .. degree_ - j] are set
};

// Doubles mapped monotonically onto integers (-0 and +0 both to 0), so that a bisection in this
// order halves the count of doubles in a bracket: <= 64 steps for any finite bracket, also over
// [0, 1e30] where halving the value would crawl through exponents.
std::int64_t Ordered(double x) {
  const auto bits = std::bit_cast<std::int64_t>(x);
  return bits >= 0 ? bits : std::numeric_limits<std::int64_t>::min() - bits;
}

double FromOrdered(std::int64_t ordered) {
  const std::int64_t bits =
      ordered >= 0 ? ordered : std::numeric_limits<std::int64_t>::min() - ordered;
  return std::bit_cast<double>(bits);
}

std::uint64_t Distance(std::int64_t a, std::int64_t b) {
  return static_cast<std::uint64_t>(b) - static_cast<std::uint64_t>(a);
}

double Midpoint(std::int64_t a, std::int64_t b) {
  return FromOrdered(static_cast<std::int64_t>(static_cast<std::uint64_t>(a) + Distance(a, b) / 2));
}

// Shrinks [left, right] to adjacent doubles (or until the step cap) keeping the invariant
// is_left(left) && !is_left(right); is_left must be how `left` and `right` were classified.
// Newton from the latest point is taken while it stays inside and its moves keep halving (the
// safeguard of rtsafe, Numerical Recipes 9.4), otherwise we bisect in the order of doubles; once
// Newton moves < 2 ulps we probe a growing number of ulps past the iterate so that the other end
// closes too. As a failsafe the bracket must halve (in doubles) every kFailsafeWindow steps.
template <typename IsLeft>
void Narrow(const DerivativeTower& tower, int level, double& left, double& right, double guess,
            IsLeft is_left) {
  constexpr int kFailsafeWindow = 8;
  std::uint64_t window_width = Distance(Ordered(left), Ordered(right));
  Real last_move = std::numeric_limits<Real>::infinity();
  Real move_before = last_move;
  std::int64_t probe = 0;
  double t = guess;
  for (int step = 0; step < kMaxNarrowSteps; ++step) {
    const std::int64_t ordered_left = Ordered(left);
    const std::int64_t ordered_right = Ordered(right);
    const std::uint64_t width = Distance(ordered_left, ordered_right);
    if (width <= 1) return;

    // Failsafe bisection, and bisection whenever the candidate left the bracket.
    bool bisect = false;
    if (step % kFailsafeWindow == kFailsafeWindow - 1) {
      bisect = width > window_width / 2;
      window_width = width;
    }
    if (bisect || std::isnan(t) || !(left < t && t < right)) {
      t = Midpoint(ordered_left, ordered_right);  // isnan first: NaN compared with < traps
    }

    // Classify t and keep the invariant.
    const Sample s = tower.Evaluate(level, t);
    const bool went_left = is_left(s);
    (went_left ? left : right) = t;

    // Next candidate: Newton while converging, then the ulp probe across the boundary. A zero
    // slope or a step out of the double range gives no Newton candidate; both are tested before
    // dividing and rounding, so no IEEE infinity is made (the tests trap them).
    const Real newton_move = s.slope != 0 ? -s.value / s.slope : Real{0};
    const bool newton_finite = s.slope != 0 && std::fabs(t + newton_move) <= kNewtonRange;
    const double newton = newton_finite ? static_cast<double>(t + newton_move) : t;
    const std::int64_t ordered_t = Ordered(t);
    if (newton_finite &&
        Distance(std::min(ordered_t, Ordered(newton)), std::max(ordered_t, Ordered(newton))) > 2) {
      const bool converging = std::fabs(newton_move) <= move_before / 2;
      t = converging ? newton : std::numeric_limits<double>::quiet_NaN();
      probe = 0;
    } else {
      probe = std::clamp<std::int64_t>(probe * 2, 2, kMaxProbeUlps);
      t = FromOrdered(went_left ? ordered_t + probe : ordered_t - probe);
    }
    move_before = last_move;
    last_move = newton_finite ? std::fabs(newton_move) : std::numeric_limits<Real>::infinity();
  }
  caps::Count(caps::root_narrowing);  // the bracket stays valid, only wider
}

// As Narrow, for a boundary expected right next to one end (`from_left`: next to `left`), as
// at the edge of the uncertainty zone around an exact or multiple root, where Newton aims at the
// root, not at the edge: gallop 1, 2, 4, ... doubles away from that end first, then narrow.
template <typename IsLeft>
void NarrowFromEnd(const DerivativeTower& tower, int level, double& left, double& right,
                   bool from_left, IsLeft is_left) {
  for (std::int64_t jump = 1; jump <= (std::int64_t{1} << 62); jump *= 2) {
    const std::int64_t ordered_left = Ordered(left);
    const std::int64_t ordered_right = Ordered(right);
    if (Distance(ordered_left, ordered_right) <= static_cast<std::uint64_t>(jump)) break;
    const double t = FromOrdered(from_left ? ordered_left + jump : ordered_right - jump);
    const bool went_left = is_left(tower.Evaluate(level, t));
    (went_left ? left : right) = t;
    if (went_left != from_left) break;  // crossed the boundary: it is now bracketed tightly
  }
  Narrow(tower, level, left, right, std::numeric_limits<double>::quiet_NaN(), is_left);
}

// Appends [lo, hi], merging with the last interval when they overlap or touch. Should the
// capacity ever run out, the last interval grows to cover the new one: a superset of root
// intervals keeps every guarantee of IsolateRealRoots.
void AddInterval(RootIntervals& out, double lo, double hi) {
  if (out.count > 0) {
    RootInterval& last = out.items[static_cast<std::size_t>(out.count - 1)];
    if (lo <= last.hi || out.count == RootIntervals::kCapacity) {
      last.hi = std::max(last.hi, hi);
      return;
    }
  }
  out.items[static_cast<std::size_t>(out.count++)] = RootInterval{lo, hi};
}

// The secant (regula falsi) point of the gap's end values: a first guess before Newton.
double SecantGuess(double x, const Sample& sx, double y, const Sample& sy) {
  const Real denominator = sy.value - sx.value;
  if (denominator == 0) return std::numeric_limits<double>::quiet_NaN();
  const Real guess = x - sx.value * (static_cast<Real>(y) - x) / denominator;
  if (std::isnan(guess) || std::fabs(guess) > kNewtonRange) {
    return std::numeric_limits<double>::quiet_NaN();
  }
  return static_cast<double>(guess);
}

// Optional closed-form estimates of the roots of level 0, used as Newton's first guess.
struct Hints {
  std::array<double, 2> roots{};
  int count = 0;

  double In(double x, double y) const {
    for (int i = 0; i < count; ++i) {
      if (x < roots[static_cast<std::size_t>(i)] && roots[static_cast<std::size_t>(i)] < y) {
        return roots[static_cast<std::size_t>(i)];
      }
    }
    return std::numeric_limits<double>::quiet_NaN();
  }
};

// One end of a gap: where it is, the sample there and the sign to use (certified, 0 if unknown).
struct GapEnd {
  double t;
  Sample sample;
  int sign;
};

// Emits the root interval (if any) of q_level on a gap [x, y] on which it is monotone.
void ProcessGap(const DerivativeTower& tower, int level, const GapEnd& x, const GapEnd& y,
                bool first_only, const Hints& hints, RootIntervals& out) {
  // Monotone with equal certified signs at both ends: no root.
  if (x.sign != 0 && x.sign == y.sign) return;

  // Uncertain at the left end: the interval starts there; find where the right sign begins.
  if (x.sign == 0) {
    double right = y.t;
    if (y.sign != 0 && !first_only) {
      double left = x.t;
      NarrowFromEnd(tower, level, left, right, /*from_left=*/true,
                    [&](const Sample& s) { return s.sign != y.sign; });
    }
    AddInterval(out, x.t, right);
    return;
  }

  // Certified at the left end, uncertain at the right end (a touching root at the critical
  // point y, or an exact root there): the interval runs from the edge of the uncertainty to y.
  double left = x.t;
  double right = y.t;
  const auto keeps_left_sign = [&](const Sample& s) { return s.sign == x.sign; };
  if (y.sign == 0) {
    NarrowFromEnd(tower, level, left, right, /*from_left=*/false, keeps_left_sign);
    AddInterval(out, left, y.t);
    return;
  }

  // A certified sign change: the interval starts after the last point with the left sign.
  double guess = hints.In(x.t, y.t);
  if (std::isnan(guess)) guess = SecantGuess(x.t, x.sample, y.t, y.sample);
  Narrow(tower, level, left, right, guess, keeps_left_sign);

  // A certified sign change usually ends at adjacent doubles; if `right` is still uncertain,
  // find where the opposite sign becomes certified (not needed for the earliest root only).
  if (!first_only && tower.Evaluate(level, right).sign == 0) {
    double uncertain = right;
    right = y.t;
    NarrowFromEnd(tower, level, uncertain, right, /*from_left=*/true,
                  [&](const Sample& s) { return s.sign != y.sign; });
  }
  AddInterval(out, left, right);
}

// Isolates the roots of q_level in [a, b] given the root intervals of q_{level+1} (outside of
// which q_level is strictly monotone).
void IsolateLevel(const DerivativeTower& tower, int level, const RootIntervals& critical, double a,
                  double b, bool first_only, const Hints& hints, RootIntervals& out) {
  GapEnd x{a, tower.Evaluate(level, a), 0};
  x.sign = x.sample.sign;
  for (int i = 0; i <= critical.count; ++i) {
    // The gap up to the next critical interval (or to b); a certified enclosure of the critical
    // interval also certifies the sign at its ends.
    const bool last = i == critical.count;
    const double y_t = last ? b : critical[i].lo;
    GapEnd y{y_t, tower.Evaluate(level, y_t), 0};
    const int critical_sign = last ? 0 : tower.EnclosureSign(level, critical[i].lo, critical[i].hi);
    y.sign = y.sample.sign != 0 ? y.sample.sign : critical_sign;
    ProcessGap(tower, level, x, y, first_only, hints, out);
    if (last || (first_only && out.count > 0)) return;

    // The critical interval itself: a root interval unless its sign is certified.
    if (critical_sign == 0) AddInterval(out, critical[i].lo, critical[i].hi);
    if (first_only && out.count > 0) return;
    x = GapEnd{critical[i].hi, tower.Evaluate(level, critical[i].hi), 0};
    x.sign = x.sample.sign != 0 ? x.sample.sign : critical_sign;
  }
}

}  // namespace

CertifiedValue EvaluateCertified(const Polynomial& p, double t) {
  const int degree = std::max(p.Degree(), 0);
  Real c[kCoefficientCount] = {};
  for (int i = 0; i <= degree; ++i) c[i] = p.Coefficient(i);
  const Sample s = EvaluateCoefficients(c, degree, t);
  return CertifiedValue{s.value, s.bound};
}

double RootMagnitudeBound(const Polynomial& p) {
  const int n = p.Degree();
  SPARSEDYN_ASSERT(n >= 1, "RootMagnitudeBound needs a non-constant polynomial");
  const int leading_exponent = std::ilogb(p.Coefficient(n));
  int best = INT_MIN;
  for (int k = 1; k <= n; ++k) {
    const double c = p.Coefficient(n - k);
    if (c == 0.0) continue;
    // |c / c_n| < 2^e, hence |c / c_n|^(1/k) < 2^ceil(e / k).
    const int e = std::ilogb(c) + 1 - leading_exponent;
    best = std::max(best, e >= 0 ? (e + k - 1) / k : -((-e) / k));
  }
  if (best == INT_MIN) return 0.0;  // p = c_n t^n: every root is 0
  // Past the double range the bound is +infinity, said so rather than made by an overflowing
  // ldexp (which the tests' floating-point traps would stop).
  if (best + 1 >= std::numeric_limits<double>::max_exponent) {
    return std::numeric_limits<double>::infinity();
  }
  // Fujiwara (1916): |z| <= 2 max_k |c_{n-k} / c_n|^(1/k). Never round a bound down to 0.
  return std::max(std::ldexp(1.0, best + 1), std::numeric_limits<double>::denorm_min());
}

RootIntervals IsolateRealRoots(const Polynomial& p, double lo, double hi, bool first_only) {
  SPARSEDYN_ASSERT(std::isfinite(lo) && std::isfinite(hi) && lo <= hi,
                   "IsolateRealRoots needs a finite interval with lo <= hi");
  RootIntervals out;
  const int n = p.Degree();
  if (n < 0) {
    AddInterval(out, lo, hi);  // every t is a root of the zero polynomial
    return out;
  }
  if (n == 0) return out;

  // No root lies outside the magnitude bound, so neither do the derivatives' (Gauss-Lucas).
  const double bound = RootMagnitudeBound(p);
  const double a = std::max(lo, -bound);
  const double b = std::min(hi, bound);
  if (a > b) return out;

  // The closed-form quadratic gives Newton a start next to the root.
  Hints hints;
  if (n == 2) {
    hints.count = SolveQuadratic(p.Coefficient(2), p.Coefficient(1), p.Coefficient(0), hints.roots);
  }

  // From the linear q_{n-1} (the constant q_n has no roots) down to q_0 = p.
  const DerivativeTower tower(p);
  RootIntervals levels[2];  // ping-pong: the critical intervals and this level's roots
  const Hints no_hints;
  for (int level = n - 1; level >= 0; --level) {
    const RootIntervals& critical = levels[(level + 1) % 2];
    RootIntervals& roots = levels[level % 2];
    roots.count = 0;
    IsolateLevel(tower, level, critical, a, b, first_only && level == 0,
                 level == 0 ? hints : no_hints, roots);
  }
  return levels[0];
}

}  // namespace sparsedyn
