// SPDX-License-Identifier: MIT
// The detailed phase's core (thesis §5, App. J): closest features of two convex polyhedra by a
// Lin-Canny walk over Voronoi regions, made robust the way V-Clip is.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "sparsedyn/geometry/convex_polyhedron.hpp"
#include "sparsedyn/geometry/pose.hpp"

namespace sparsedyn {

/// One feature of each polyhedron.
struct FeaturePair {
  /// The feature of A.
  FeatureId a;
  /// The feature of B.
  FeatureId b;
  /// Pairs are equal when both features are.
  friend bool operator==(const FeaturePair&, const FeaturePair&) = default;
};

/// What a closest-feature query found.
struct ClosestFeatures {
  /// How the query ended.
  enum class Status : std::uint8_t {
    kSeparated,      ///< distance > 0
    kPenetrating,    ///< distance <= 0: the polyhedra touch or overlap; distance = -depth
    kIterationCap,   ///< the walk did not finish within ClosestFeaturesOptions::max_steps
  };
  /// How the query ended.
  Status status = Status::kSeparated;
  double distance = 0.0;                              ///< signed; negative = penetration depth
  Eigen::Vector3d point_a = Eigen::Vector3d::Zero();  ///< witness on A, world frame
  Eigen::Vector3d point_b = Eigen::Vector3d::Zero();  ///< witness on B, world frame
  Eigen::Vector3d normal = Eigen::Vector3d::UnitX();  ///< unit, world frame, from A towards B
  FeaturePair features;                               ///< the closest feature pair
  int steps = 0;                                      ///< walk steps taken (features visited - 1)
};

/// How the walk starts and when it gives up.
struct ClosestFeaturesOptions {
  int max_steps = 10000;             ///< iteration cap: beyond it Status::kIterationCap
  bool use_angle_tables = true;      ///< App. J.1.1 for faces and vertices with many edges
  bool use_direction_table = true;   ///< App. J.1.2 for cold starts
};

/// A ConvexPolyhedron with the tables the walk uses (App. J.1.1 angle tables, App. J.1.2
/// direction -> starting feature table), built once and shared by every pair it takes part in.
class TrackedPolyhedron {
 public:
  /// Builds the tables of `polyhedron` (shared, not copied).
  explicit TrackedPolyhedron(std::shared_ptr<const ConvexPolyhedron> polyhedron);
  ~TrackedPolyhedron();
  /// Moves the polyhedron and its tables.
  TrackedPolyhedron(TrackedPolyhedron&&) noexcept;
  /// Moves the polyhedron and its tables.
  TrackedPolyhedron& operator=(TrackedPolyhedron&&) noexcept;

  /// The polyhedron.
  const ConvexPolyhedron& polyhedron() const { return *polyhedron_; }
  /// The feature the J.1.2 table proposes as closest to a far point in body-frame direction d.
  FeatureId StartingFeature(const Eigen::Vector3d& direction_B) const;
  /// The support vertex in body-frame direction d (as ConvexPolyhedron::SupportVertex, up to
  /// ties): the J.1.2 table's vertex for d, climbed to the maximum; a few dot products
  /// instead of one per vertex.
  int SupportVertex(const Eigen::Vector3d& direction_B) const;

  class Tables;  ///< defined in src/narrow/
  const Tables& tables() const { return *tables_; }

 private:
  std::shared_ptr<const ConvexPolyhedron> polyhedron_;
  std::unique_ptr<Tables> tables_;
};

/// Closest features of A placed at X_WA and B placed at X_WB. `start` warm-starts the walk from
/// a previous answer (coherence); without it the walk cold-starts from the direction table (or
/// vertex 0 of each when options.use_direction_table is false). Every step strictly lowers the
/// distance between the current features, or keeps it and lowers a feature's dimension, so the
/// walk terminates and cannot cycle; the answer does not depend on the start.
ClosestFeatures FindClosestFeatures(const TrackedPolyhedron& a, const Pose& X_WA,
                                    const TrackedPolyhedron& b, const Pose& X_WB,
                                    std::optional<FeaturePair> start = std::nullopt,
                                    const ClosestFeaturesOptions& options = {});

/// A paste-able description of one query for tests/regression/ (STYLE.md §4): both polyhedra as
/// PolygonMesh literals and both poses at 17 significant digits, and the start pair ("cold" when
/// none). Used for a walk that hit the iteration cap.
std::string DescribeQuery(const TrackedPolyhedron& a, const Pose& X_WA, const TrackedPolyhedron& b,
                          const Pose& X_WB, std::optional<FeaturePair> start = std::nullopt);

/// Follows one pair over time: each Update warm-starts from the previous answer. Counts calls,
/// steps and iteration-cap failures (tests assert the last stays 0).
class ClosestFeatureTracker {
 public:
  /// Follows a and b (both must outlive the tracker); the first Update cold-starts.
  ClosestFeatureTracker(const TrackedPolyhedron& a, const TrackedPolyhedron& b,
                        ClosestFeaturesOptions options = {});

  /// The closest features at these poses, warm-started from the last answer.
  const ClosestFeatures& Update(const Pose& X_WA, const Pose& X_WB);
  /// Forget the cached pair: the next Update cold-starts.
  void Reset() { has_last_ = false; }
  /// The last answer.
  const ClosestFeatures& last() const { return last_; }

  /// Update calls so far.
  std::uint64_t calls() const { return calls_; }
  /// Walk steps over all calls.
  std::uint64_t steps() const { return steps_; }
  /// Calls that hit the iteration cap (0 in every test).
  std::uint64_t iteration_cap_failures() const { return cap_failures_; }
  /// DescribeQuery() of the last query that hit the iteration cap; empty if none did.
  const std::string& last_failure() const { return last_failure_; }

 private:
  const TrackedPolyhedron* a_;
  const TrackedPolyhedron* b_;
  ClosestFeaturesOptions options_;
  ClosestFeatures last_;
  bool has_last_ = false;
  std::uint64_t calls_ = 0, steps_ = 0, cap_failures_ = 0;
  std::string last_failure_;
};

}  // namespace sparsedyn
