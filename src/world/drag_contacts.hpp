// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <optional>

#include "motion/rigid_path.hpp"
#include "sparse/mover.hpp"
#include "sparsedyn/geometry/convex_polyhedron.hpp"
#include "sparsedyn/narrow/closest_features.hpp"
#include "world/box_walls.hpp"
#include "world/world_core.hpp"

namespace sparsedyn {

/// Contact times of bodies with drag on their TRUE motions (App. E's convergence, App. H.2):
/// conservative advancement over local Taylor segments of the DragMotions whose envelopes
/// shrink with the gap (docs/dynamics.md, "Drag in the World"). From time t with true gap g,
/// each body's segment about t gets max_error = g/8 (a pair) or g/4 (a wall); the first time
/// the quadratic paths' gap minus both envelopes reaches 0 (PredictMeeting, never late) is a
/// time before which the true bodies cannot touch, and at which their true gap is at most half
/// of g. So the gap halves or better per step, down to the contact band (contact_tolerance times
/// the summed radii), where the envelopes are below an eighth of the band: the contact is
/// reported there, never late and inside the band. A body without drag takes part with its
/// exact path (no envelope).
class DragContacts {
 public:
  explicit DragContacts(WorldCore& core) : core_(core) {}

  /// The first time in [begin, end) at which bodies i and j (j's periodic image at `shift`;
  /// one of them at least with drag) touch within the contact band while approaching, on their
  /// true motions; a time before it when kIterationsPerPrediction steps did not finish (an
  /// early event that predicts again from there); kInfinity when they do not touch before end.
  /// begin >= now.
  double PairContact(std::uint32_t i, std::uint32_t j, const Vec3& shift, double begin,
                     double end);
  /// The same for body i (with drag) and the wall `plane`.
  double WallContact(std::uint32_t i, const WallPlane& plane, double begin, double end);
  /// Body i's (with drag) first contact with a wall of the walled box before `end`, its wall
  /// in `wall`: the element (its envelope included) reaches the wall no later than the body,
  /// from there WallContact. The walls that hold i are left out (it moves along them).
  double FirstWallContact(std::uint32_t i, double end, std::uint8_t& wall);
  /// The same for body i (a sphere with drag) and static body s, whose pair's contact band is
  /// `band` (StaticContacts::Tolerance). A static polyhedron is met by i's local sphere with
  /// its radius grown by the envelope's bound (PredictSphereContact to an eighth of the band);
  /// `feature` is the polyhedron's closest feature, warm start in and the last walk's out.
  double StaticContact(std::uint32_t i, std::uint32_t s, double band, double begin, double end,
                       std::optional<FeatureId>& feature);

  /// One side of a polyhedron's contact on true motions: a moving body (its image at `shift`),
  /// or a static one (body kNoIndex) fixed on `fixed`, with its `shape` if a polyhedron.
  struct Side {
    std::uint32_t body = kNoIndex;
    Vec3 shift = Vec3::Zero();
    RigidPath fixed;
    const TrackedPolyhedron* shape = nullptr;
  };
  /// Polyhedra with drag (docs/dynamics.md, "Drag in the World"): the same advancement, each
  /// step the detailed phase's own prediction (narrow/time_of_contact.hpp) on the local Taylor
  /// paths with its tolerance grown by both envelopes. The first time in [begin, end) at which
  /// polyhedra a and b (one of them at least with drag) are within 3/4 of `band` on their true
  /// motions, never later than the first time they are within band/8; a time before it when
  /// kIterationsPerPrediction steps did not finish; kInfinity when none before end. `features`:
  /// the pair's warm start in, the last walk's out. Whether a point approaches is the handler's
  /// question.
  double PolyhedraContact(const Side& a, const Side& b, double band, double begin, double end,
                          std::optional<FeaturePair>& features);
  /// The same for polyhedron side p and the sphere of `radius` on side s (`feature`: the
  /// polyhedron's closest to the centre).
  double PolyhedronSphereContact(const Side& p, const Side& s, double radius, double band,
                                 double begin, double end, std::optional<FeatureId>& feature);
  /// The same for polyhedron i (with drag) and the wall `plane`.
  double PolyhedronWallContact(std::uint32_t i, const WallPlane& plane, double band,
                               double begin, double end);

 private:
  // A side's rigid path about t within `error` of its true motion over `horizon`.
  struct LocalRigid {
    RigidPath path;
    double horizon;
    double error;
  };
  LocalRigid LocalRigidAt(const Side& side, double t, double max_error, double max_horizon) const;
  // A side's pose at t on its true motion.
  Pose TruePoseOf(const Side& side, double t) const;
  double SpinRadiusOf(const Side& side) const;
  const TrackedPolyhedron& ShapeOf(const Side& side) const;
  // The advancement shared by the polyhedra: `gap_at(t)`, the true gap; `step(t, max_error)`,
  // the next time, from t, at which the local paths may be within the band.
  template <typename GapAt, typename Step>
  double Advance(double band, double begin, double end, GapAt&& gap_at, Step&& step);
  // Body i's sphere on its true motion about t: the local Taylor segment with envelope at most
  // max_error over its horizon, or the exact path of a body without drag.
  struct Local {
    Mover mover;
    Path path;
    double horizon;
  };
  Local LocalAt(std::uint32_t i, double t, double max_error, double max_horizon) const;
  // Body i's true position and velocity at t.
  struct BodyNow {
    Vec3 position;
    Vec3 velocity;
  };
  BodyNow TrueStateOf(std::uint32_t i, double t) const;

  WorldCore& core_;
};

}  // namespace sparsedyn
