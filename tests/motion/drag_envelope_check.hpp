// SPDX-License-Identifier: MIT
#pragma once

// Random drag bodies and the dense-sampling check that their true motion stays inside the
// envelope of DragMotion::SegmentFor, shared by the fast and the slow envelope tests.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "motion/drag_motion.hpp"
#include "motion/drag_oracles.hpp"
#include "motion/drag_stepper.hpp"

namespace sparsedyn::testing {

/// One random body: start, constant acceleration, drag, the time of the check and the
/// envelope's allowance (a fraction of a radius).
struct DragBody {
  double t0, t;
  Vec3 p0, v0, g;
  Drag drag;
  double max_error;

  std::string Describe() const {
    std::ostringstream s;
    s.precision(17);
    s << "DragBody{" << t0 << ", " << t << ", {" << p0.transpose() << "}, {" << v0.transpose()
      << "}, {" << g.transpose() << "}, {" << drag.linear << ", " << drag.quadratic << "}, "
      << max_error << "}";
    return s.str();
  }
};

inline DragBody RandomDragBody(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  auto log_uniform = [&](double lo, double hi) {
    return std::exp(std::log(lo) + unit(rng) * (std::log(hi) - std::log(lo)));
  };
  auto direction = [&] {
    std::normal_distribution<double> n(0.0, 1.0);
    Vec3 d(n(rng), n(rng), n(rng));
    return Vec3(d / d.norm());
  };
  DragBody b;
  b.t0 = unit(rng) < 0.5 ? 0.0 : 100.0 * unit(rng);
  b.p0 = log_uniform(0.1, 100.0) * direction();
  const double kind = unit(rng);
  b.g = kind < 0.1 ? Vec3(Vec3::Zero()) : Vec3(log_uniform(0.1, 30.0) * direction());
  if (kind > 0.9) b.g = Vec3(0, 0, -9.81);
  b.v0 = unit(rng) < 0.1 ? Vec3(Vec3::Zero()) : Vec3(log_uniform(0.01, 100.0) * direction());
  const double which = unit(rng);  // a third linear only, a third quadratic only, both
  b.drag.linear = which < 2.0 / 3.0 ? log_uniform(1e-3, 10.0) : 0.0;
  b.drag.quadratic = which > 1.0 / 3.0 ? log_uniform(1e-3, 10.0) : 0.0;
  // The check at the segment start (the World's use), sometimes later in the segment.
  b.t = b.t0 + (unit(rng) < 0.7 ? 0.0 : log_uniform(1e-3, 1.0));
  b.max_error = 1e-3 * log_uniform(0.01, 1.0);
  return b;
}

/// The largest ratio |x(t') - P(t')| / E(t' - t) over `samples` sample times t' in the
/// envelope's horizon (capped at `max_span`), with the positions DragMotion reports: for the
/// integrator by one walk of its steps (the same bits as PositionAt, which `spot_checks` of
/// them confirm), and for the closed form also the exact motion (the textbook formula in
/// 128-bit floats). Distances are measured in long double against the path evaluated in
/// long double at the exact offset t' - t.
inline double WorstEnvelopeRatio(const DragBody& b, int samples, double max_span, int spot_checks,
                                 double* horizon_out = nullptr) {
  const DragMotion motion(b.t0, b.p0, b.v0, b.g, b.drag);
  const TaylorSegment seg = motion.SegmentFor(b.t, b.max_error);
  if (horizon_out) *horizon_out = seg.horizon;
  EXPECT_LE(seg.envelope.At(std::min(seg.horizon, 1e300)), b.max_error * (1.0 + 1e-12));
  const double span = std::min(seg.horizon, max_span);
  std::mt19937_64 rng(static_cast<std::uint64_t>(b.t0 * 1e6) ^ 0x9e3779b97f4a7c15ull);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<double> times = {b.t, b.t + span};
  for (int i = 0; i < samples; ++i) times.push_back(b.t + span * unit(rng));
  std::sort(times.begin(), times.end());
  const Path& p = seg.path;
  std::optional<DragStepper> stepper;
  DragFlow flow;
  if (!motion.IsClosedForm()) {
    flow = DragFlow::Make(DragModel{b.g, b.drag.linear, b.drag.quadratic}, b.v0);
    stepper.emplace(flow, b.p0, b.v0);
  }
  double worst = 0.0;
  for (std::size_t i = 0; i < times.size(); ++i) {
    const double t = times[i];
    if (t > b.t + span) continue;
    const long double tau = static_cast<long double>(t) - p.t0;
    std::array<long double, 3> path_x;
    for (int k = 0; k < 3; ++k) {
      path_x[k] = p.p0[k] + tau * (p.v0[k] + 0.5L * tau * p.a[k]);
    }
    const long double allowed =
        seg.envelope.e0 + tau * (seg.envelope.e1 + 0.5L * seg.envelope.e2 * tau);
    Vec3 x;
    if (stepper) {
      const double dt = t - b.t0;
      stepper->AdvanceTo(dt);
      x = stepper->Evaluate(dt).position;
      if (static_cast<int>(i) < spot_checks) {
        EXPECT_EQ(x, motion.PositionAt(t));
      }
    } else {
      x = motion.PositionAt(t);
      if (b.drag.linear > 0.0) {
        const QuadState q =
            TextbookLinearDrag(b.p0, b.v0, b.g, b.drag.linear, static_cast<Quad>(t) - b.t0);
        std::array<long double, 3> exact;
        for (int k = 0; k < 3; ++k) exact[k] = static_cast<long double>(q.x[k]);
        long double d2 = 0;
        for (int k = 0; k < 3; ++k) d2 += (exact[k] - path_x[k]) * (exact[k] - path_x[k]);
        worst = std::max(worst, static_cast<double>(std::sqrt(d2) / allowed));
      }
    }
    long double d2 = 0;
    for (int k = 0; k < 3; ++k) d2 += (x[k] - path_x[k]) * (x[k] - path_x[k]);
    worst = std::max(worst, static_cast<double>(std::sqrt(d2) / allowed));
  }
  return worst;
}

}  // namespace sparsedyn::testing
