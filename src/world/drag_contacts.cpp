// SPDX-License-Identifier: MIT
#include "world/drag_contacts.hpp"

#include <algorithm>
#include <cmath>

#include "math/event_time.hpp"
#include "narrow/point_features.hpp"
#include "narrow/sphere_contact.hpp"
#include "narrow/time_of_contact.hpp"
#include "sparse/meeting.hpp"
#include "world/contact_band.hpp"

namespace sparsedyn {
namespace {

// The share of the true gap each envelope may take in a step: a pair's two envelopes then sum
// to a quarter of the gap and a wall's one to a quarter, so the true gap where the paths'
// spheres meet is at most half the gap before (the paths' gap is 0 there, the true one within
// the envelopes of it on either side).
constexpr double kPairErrorShare = 0.125;
constexpr double kWallErrorShare = 0.25;
// A contact is reported where the true gap is within half the band and clearly closing, so
// that the handler, which asks for the band and any closing with other roundings of the same
// state, never finds it early (the steps converge to half the band: see the shares above).
constexpr double kAcceptShare = 0.5;
constexpr double kClosingMargin = 1e-12;
// Polyhedra: a step's prediction is asked for the envelopes plus this share of the band (over
// kAdvancementTarget, which a rotating pair's advancement stops short by), so the true bodies
// stay at least that far apart before the step's end, and a step from a gap within the band
// ends at most 2/3 of the band apart: accepted below 3/4 of it.
constexpr double kStepBandShare = 0.125;
constexpr double kPolyhedronAcceptShare = 0.75;

// The next time after t that a step reaches: EventTime(t, dt), but at least one ulp on (a gap
// wider than the band takes time to close, so this is not late).
double StepTo(double t, double dt) {
  const double next = EventTime(t, dt);
  return next > t ? next : std::nextafter(t, kInfinity);
}

// Where the next step starts: the paths' meeting dt after t, or the end of the horizon h of
// the local segments when they do not meet within it (infinity: never).
double NextStart(double t, double dt, double h) {
  if (dt != kInfinity) return StepTo(t, dt);
  return h == kInfinity ? kInfinity : StepTo(t, h);
}

}  // namespace

DragContacts::Local DragContacts::LocalAt(std::uint32_t i, double t, double max_error,
                                         double max_horizon) const {
  const BodyStore& bodies = core_.bodies;
  const double radius = bodies.materials.Radius(i);
  if (!bodies.HasDrag(i)) {
    return Local{bodies.BodyMoverOf(i, t), bodies.paths.PathOf(i), kInfinity};
  }
  const TaylorSegment segment =
      bodies.paths.drags().LocalSegment(i, t, max_error, max_horizon);
  return Local{MoverAt(segment.path, radius, segment.envelope, t), segment.path,
               segment.horizon};
}

DragContacts::BodyNow DragContacts::TrueStateOf(std::uint32_t i, double t) const {
  // One evaluation of the DragMotion for both (the integrator walks from its start each time).
  const ElementPaths& paths = core_.bodies.paths;
  if (!paths.drags().Has(i)) {
    const Path path = paths.PathOf(i);
    return BodyNow{path.PositionAt(t), path.VelocityAt(t)};
  }
  const DragState state = paths.drags().StateAt(i, t);
  return BodyNow{state.position, state.velocity};
}

double DragContacts::PairContact(std::uint32_t i, std::uint32_t j, const Vec3& shift,
                                 double begin, double end) {
  const double reach = core_.bodies.materials.Radius(i) + core_.bodies.materials.Radius(j);
  const double band = core_.settings.contact_tolerance * reach;
  Statistics& stats = core_.observers.stats();
  double t = begin;
  for (int step = 0; step < kIterationsPerPrediction; ++step) {
    if (!(t < end)) return kInfinity;
    // The true gap at t, and whether it closes: in the band and closing is the contact.
    const BodyNow a_now = TrueStateOf(i, t), b_now = TrueStateOf(j, t);
    const Vec3 d = b_now.position + shift - a_now.position;
    const Vec3 dv = b_now.velocity - a_now.velocity;
    const double distance = d.norm();
    const double gap = distance - reach;
    const bool closing = d.dot(dv) < -kClosingMargin * distance * dv.norm();
    if (gap <= kAcceptShare * band && closing) return t;
    // The paths' spheres about t with envelopes below a share of the gap (or of the band).
    ++stats.drag_steps;
    const double max_error = kPairErrorShare * std::max(gap, band);
    const Local a = LocalAt(i, t, max_error, end - t);
    const Local b = LocalAt(j, t, max_error, end - t);
    const double h = std::min({a.horizon, b.horizon, end - t});
    const double dt = PredictMeeting(a.mover, b.mover, shift, h);
    if (gap <= band && !(dt > 0)) {
      // Touching without closing (a pair that has just collided, a graze): not before the band
      // could have been closed.
      t = BandExit(t, band, dv.norm() + a.mover.r1 + b.mover.r1,
                   (b.mover.a - a.mover.a).norm() + a.mover.r2 + b.mover.r2);
    } else {
      t = NextStart(t, dt, h);
    }
  }
  return t;  // unfinished: looked at again from here
}

double DragContacts::WallContact(std::uint32_t i, const WallPlane& plane, double begin,
                                 double end) {
  const double radius = core_.bodies.materials.Radius(i);
  const double band = core_.settings.contact_tolerance * radius;
  Statistics& stats = core_.observers.stats();
  double t = begin;
  for (int step = 0; step < kIterationsPerPrediction; ++step) {
    if (!(t < end)) return kInfinity;
    const BodyNow now = TrueStateOf(i, t);
    const double gap = plane.normal.dot(now.position) - plane.offset - radius;
    const Vec3& v = now.velocity;
    const double approach = plane.normal.dot(v);
    if (gap <= kAcceptShare * band && approach < -kClosingMargin * v.norm()) return t;
    ++stats.drag_steps;
    const Local a = LocalAt(i, t, kWallErrorShare * std::max(gap, band), end - t);
    const double h = std::min(a.horizon, end - t);
    const double dt = PredictWallMeeting(a.mover, plane.normal, plane.offset, h);
    if (gap <= band && !(dt > 0)) {
      t = BandExit(t, band, std::abs(approach) + a.mover.r1, a.mover.a.norm() + a.mover.r2);
    } else {
      t = NextStart(t, dt, h);
    }
  }
  return t;
}

double DragContacts::StaticContact(std::uint32_t i, std::uint32_t s, double band, double begin,
                                   double end, std::optional<FeatureId>& feature) {
  const BodyStore& bodies = core_.bodies;
  const StaticBodies::Static& st = bodies.statics[s];
  const double radius = bodies.materials.Radius(i);
  const TrackedPolyhedron* polyhedron =
      st.shape == kNoIndex ? nullptr : bodies.rigid.shapes()[st.shape].tracked.get();
  const RigidPath fixed_path{Path{st.pose.translation, Vec3::Zero(), Vec3::Zero(), begin},
                             st.pose.rotation, Vec3::Zero()};
  const Mover fixed{st.pose.translation, Vec3::Zero(), Vec3::Zero(), st.radius, 0.0, 0.0};
  Statistics& stats = core_.observers.stats();
  double t = begin;
  for (int step = 0; step < kIterationsPerPrediction; ++step) {
    if (!(t < end)) return kInfinity;
    // The true gap at t along the normal from the static to the centre, and whether it closes.
    const BodyNow now = TrueStateOf(i, t);
    Vec3 normal;
    double gap = 0.0;
    if (polyhedron != nullptr) {
      const PointClosest closest =
          FindClosestFeatureToPoint(*polyhedron, st.pose, now.position, feature);
      feature = closest.feature;
      normal = closest.normal;
      gap = closest.distance - radius;
    } else {
      const Vec3 d = now.position - st.pose.translation;
      const double distance = d.norm();
      normal = d / distance;
      gap = distance - radius - st.radius;
    }
    const Vec3& v = now.velocity;
    if (gap <= kAcceptShare * band && normal.dot(v) < -kClosingMargin * v.norm()) return t;
    ++stats.drag_steps;
    // A pair's share although the static is exact: a polyhedron's contact is reported within
    // an eighth of the band, and the step must still end within half the gap.
    const double max_error = kPairErrorShare * std::max(gap, band);
    const Local a = LocalAt(i, t, max_error, end - t);
    const double h = std::min(a.horizon, end - t);
    double dt = kInfinity;
    if (polyhedron != nullptr) {
      // The local sphere grown by the envelope's bound holds the true one over the horizon:
      // it reaches the polyhedron no later, where the true gap is at most 2 max_error + band/8.
      ContactPredictionOptions options;
      options.tolerance = 0.125 * band;
      options.max_iterations = kIterationsPerPrediction;
      options.spin_radius_a = 0.0;
      const SphereContactPrediction p =
          PredictSphereContact(*polyhedron, fixed_path, a.path, radius + max_error, t, t + h,
                               feature, options);
      stats.detail_iterations += static_cast<std::uint64_t>(p.iterations);
      if (p.kind != ContactPrediction::Kind::kNone) {
        feature = p.closest.feature;
        dt = std::max(0.0, p.time - t);
      }
    } else {
      dt = PredictMeeting(a.mover, fixed, Vec3::Zero(), h);
    }
    if (gap <= band && !(dt > 0)) {
      t = BandExit(t, band, v.norm() + a.mover.r1, a.mover.a.norm() + a.mover.r2);
    } else {
      t = NextStart(t, dt, h);
    }
  }
  return t;
}

DragContacts::LocalRigid DragContacts::LocalRigidAt(const Side& side, double t, double max_error,
                                                   double max_horizon) const {
  if (side.body == kNoIndex) return LocalRigid{side.fixed, kInfinity, 0.0};
  const BodyStore& bodies = core_.bodies;
  RigidPath path = bodies.RigidPathOf(side.body);
  if (!bodies.HasDrag(side.body)) {
    path.centre.p0 += side.shift;
    return LocalRigid{path, kInfinity, 0.0};
  }
  const TaylorSegment segment =
      bodies.paths.drags().LocalSegment(side.body, t, max_error, max_horizon);
  RigidPath local{segment.path, path.OrientationAt(segment.path.t0).normalized(), path.omega};
  local.centre.p0 += side.shift;
  return LocalRigid{local, segment.horizon, max_error};
}

Pose DragContacts::TruePoseOf(const Side& side, double t) const {
  if (side.body == kNoIndex) return side.fixed.PoseAt(t);
  const BodyStore& bodies = core_.bodies;
  return Pose{bodies.RigidPathOf(side.body).OrientationAt(t),
              bodies.paths.TruePositionAt(side.body, t) + side.shift};
}

double DragContacts::SpinRadiusOf(const Side& side) const {
  return side.body == kNoIndex ? 0.0 : core_.bodies.rigid.SpinRadius(side.body);
}

const TrackedPolyhedron& DragContacts::ShapeOf(const Side& side) const {
  return side.body == kNoIndex ? *side.shape : *core_.bodies.rigid.ShapeOf(side.body).tracked;
}

template <typename GapAt, typename Step>
double DragContacts::Advance(double band, double begin, double end, GapAt&& gap_at,
                             Step&& step) {
  Statistics& stats = core_.observers.stats();
  double t = begin;
  for (int k = 0; k < kIterationsPerPrediction; ++k) {
    if (!(t < end)) return kInfinity;
    const double gap = gap_at(t);
    if (gap <= kPolyhedronAcceptShare * band) return t;
    ++stats.drag_steps;
    // Each envelope below an eighth of the gap: the step ends where the true gap is at most
    // about half of it (or 2/3 of the band).
    t = step(t, kPairErrorShare * std::max(gap, band));
  }
  return t;  // unfinished: looked at again from here
}

namespace {

// A step's prediction for local paths with envelopes e_a and e_b: asked for both plus an
// eighth of the band, over the rotating pair's advancement target.
ContactPredictionOptions StepOptions(double e_a, double e_b, double band, double spin_a,
                                     double spin_b) {
  ContactPredictionOptions options;
  options.tolerance = (e_a + e_b + kStepBandShare * band) / kAdvancementTarget;
  options.max_iterations = kIterationsPerPrediction;
  options.spin_radius_a = spin_a;
  options.spin_radius_b = spin_b;
  return options;
}

// Where a step ends: at the prediction's time (at least an ulp on), or past the horizon h.
double StepEnd(double t, ContactPrediction::Kind kind, double time, double h) {
  if (kind == ContactPrediction::Kind::kNone) return NextStart(t, kInfinity, h);
  return time > t ? time : std::nextafter(t, kInfinity);
}

}  // namespace

double DragContacts::PolyhedraContact(const Side& a, const Side& b, double band, double begin,
                                      double end, std::optional<FeaturePair>& features) {
  const TrackedPolyhedron& shape_a = ShapeOf(a);
  const TrackedPolyhedron& shape_b = ShapeOf(b);
  Statistics& stats = core_.observers.stats();
  const auto gap_at = [&](double t) {
    const ClosestFeatures closest =
        FindClosestFeatures(shape_a, TruePoseOf(a, t), shape_b, TruePoseOf(b, t), features);
    features = closest.features;
    return closest.distance;
  };
  const auto step = [&](double t, double max_error) {
    const LocalRigid la = LocalRigidAt(a, t, max_error, end - t);
    const LocalRigid lb = LocalRigidAt(b, t, max_error, end - t);
    const double h = std::min({la.horizon, lb.horizon, end - t});
    const ContactPrediction p = PredictContact(
        shape_a, la.path, shape_b, lb.path, t, t + h, features,
        StepOptions(la.error, lb.error, band, SpinRadiusOf(a), SpinRadiusOf(b)));
    stats.detail_iterations += static_cast<std::uint64_t>(p.iterations);
    features = p.features.features;
    return StepEnd(t, p.kind, p.time, h);
  };
  return Advance(band, begin, end, gap_at, step);
}

double DragContacts::PolyhedronSphereContact(const Side& p, const Side& s, double radius,
                                             double band, double begin, double end,
                                             std::optional<FeatureId>& feature) {
  const TrackedPolyhedron& shape = ShapeOf(p);
  Statistics& stats = core_.observers.stats();
  const auto gap_at = [&](double t) {
    const PointClosest closest =
        FindClosestFeatureToPoint(shape, TruePoseOf(p, t), TruePoseOf(s, t).translation, feature);
    feature = closest.feature;
    return closest.distance - radius;
  };
  const auto step = [&](double t, double max_error) {
    const LocalRigid lp = LocalRigidAt(p, t, max_error, end - t);
    const LocalRigid ls = LocalRigidAt(s, t, max_error, end - t);
    const double h = std::min({lp.horizon, ls.horizon, end - t});
    const SphereContactPrediction q =
        PredictSphereContact(shape, lp.path, ls.path.centre, radius, t, t + h, feature,
                             StepOptions(lp.error, ls.error, band, SpinRadiusOf(p), -1.0));
    stats.detail_iterations += static_cast<std::uint64_t>(q.iterations);
    if (q.kind != ContactPrediction::Kind::kNone) feature = q.closest.feature;
    return StepEnd(t, q.kind, q.time, h);
  };
  return Advance(band, begin, end, gap_at, step);
}

double DragContacts::PolyhedronWallContact(std::uint32_t i, const WallPlane& plane, double band,
                                           double begin, double end) {
  const Side side{i};
  const TrackedPolyhedron& shape = ShapeOf(side);
  const ConvexPolyhedron& polyhedron = *core_.bodies.rigid.ShapeOf(i).polyhedron;
  Statistics& stats = core_.observers.stats();
  const auto gap_at = [&](double t) {
    const Pose pose = TruePoseOf(side, t);
    const int nearest = shape.SupportVertex(-(pose.rotation.conjugate() * plane.normal));
    return plane.normal.dot(pose.ToWorld(polyhedron.vertex(nearest))) - plane.offset;
  };
  const auto step = [&](double t, double max_error) {
    const LocalRigid local = LocalRigidAt(side, t, max_error, end - t);
    const double h = std::min(local.horizon, end - t);
    const WallContactPrediction p = PredictWallContact(
        shape, local.path, plane.normal, plane.offset, t, t + h,
        StepOptions(local.error, 0.0, band, 0.0, 0.0).tolerance, kIterationsPerPrediction,
        SpinRadiusOf(side));
    stats.detail_iterations += static_cast<std::uint64_t>(p.iterations);
    return StepEnd(t, p.kind, p.time, h);
  };
  return Advance(band, begin, end, gap_at, step);
}

double DragContacts::FirstWallContact(std::uint32_t i, double end, std::uint8_t& wall) {
  const BodyStore& bodies = core_.bodies;
  const double now = bodies.paths.Now();
  const Mover element = bodies.MoverOf(i, now);
  const std::uint8_t held = bodies.paths.accelerations().HeldBy(i);
  double best = kInfinity;
  wall = 0;
  for (int w = 0; w < 6; ++w) {
    if ((held >> w & 1u) != 0) continue;
    const WallPlane plane = BoxWall(core_.settings.container, w);
    // The element reaches the wall first; one that overlaps it already may hold a body that
    // touches it at any time.
    const bool overlapping = plane.normal.dot(element.p) - plane.offset <= element.r0;
    double begin = now;
    if (!overlapping) {
      const double dt = PredictWallMeeting(element, plane.normal, plane.offset);
      if (dt == kInfinity) continue;
      begin = std::max(now, EventTime(now, dt));
    }
    const double limit = std::min(end, best);
    if (!(begin < limit)) continue;
    const double t = WallContact(i, plane, begin, limit);
    if (t < best) {
      best = t;
      wall = static_cast<std::uint8_t>(w);
    }
  }
  return best;
}

}  // namespace sparsedyn
