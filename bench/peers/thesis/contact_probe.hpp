// SPDX-License-Identifier: MIT
#pragma once
// Measures what a time-stepped engine did to the thesis scene, from the body poses after each
// step (outside the timed part): the deepest penetration and the contacts it missed
// (definitions in docs/lab/measurements.md "The thesis scene against Bullet").

#include <cstdint>
#include <memory>
#include <span>
#include <unordered_map>
#include <vector>

#include "sparsedyn/geometry/pose.hpp"
#include "sparsedyn/io/scene_file.hpp"
#include "sparsedyn/narrow/closest_features.hpp"

namespace sparsedyn::bench {

/// A penetration deeper than this fraction of the bounding radius counts as a deep contact:
/// the engine let the bodies far into each other, a contact it resolved late or not at all.
inline constexpr double kDeepPenetrationFraction = 0.5;

/// Polyhedra closer than this fraction of the bounding radius count as touching: Bullet resolves
/// most contacts at a small positive gap (within its contact threshold, 0.02 here), and the
/// poses are sampled once a step, during which two bodies close by up to ~0.05 at the scene's
/// speeds.
inline constexpr double kTouchFraction = 0.05;

/// Counts over a run. An *episode* of a pair is a maximal run of consecutive measured steps in
/// which the two bounding spheres overlap.
struct ProbeTotals {
  double max_penetration = 0;       ///< deepest overlap, body-body or body-wall, m
  std::uint64_t contacts = 0;       ///< episodes in which the polyhedra came within kTouchFraction
  std::uint64_t penetrating = 0;    ///< episodes in which the polyhedra overlapped
  std::uint64_t deep_contacts = 0;  ///< episodes deeper than kDeepPenetrationFraction radius
  /// Episodes in which the polyhedra overlapped and the centres ended the episode on the other
  /// side of each other (the centre-to-centre vector at its end points against the one at its
  /// start): the bodies passed through each other instead of bouncing.
  std::uint64_t passed_through = 0;
  std::uint64_t escaped = 0;         ///< bodies whose centre left the walled box (once each)
  std::uint64_t iteration_caps = 0;  ///< closest-feature queries that hit their cap (should be 0)
  std::uint64_t queries = 0;         ///< closest-feature queries made
  /// The contacts the engine missed: passed_through + escaped.
  std::uint64_t Missed() const { return passed_through + escaped; }
};

/// Finds the pairs whose bounding spheres overlap through a uniform grid of cells one bounding
/// diameter wide, measures each pair's signed distance with FindClosestFeatures (warm-started
/// from the pair's last answer) and each wall-crossing body's deepest vertex, and keeps the
/// episodes.
class ContactProbe {
 public:
  explicit ContactProbe(const SceneDescription& scene);

  /// Measures the poses of every body (body frames of the scene shapes) after one step.
  void Measure(std::span<const Pose> X_WB);
  /// Ends the open episodes (call once after the last step) and returns the totals.
  const ProbeTotals& Finish();

 private:
  struct Episode {
    Eigen::Vector3d d0 = Eigen::Vector3d::Zero();  // centre of b minus centre of a at the start
    Eigen::Vector3d d = Eigen::Vector3d::Zero();   // the same at the last measured step
    std::optional<FeaturePair> warm;
    std::uint64_t seen = 0;  // the last measurement that found the pair
    bool touched = false;
    bool overlapped = false;
    bool deep = false;
  };

  void FindPairs(std::span<const Pose> X_WB);
  void MeasurePair(std::uint32_t a, std::uint32_t b, std::span<const Pose> X_WB);
  void MeasureWalls(std::uint32_t i, const Pose& X_WB);
  void EndEpisode(const Episode& episode);

  const SceneDescription& scene_;
  std::vector<TrackedPolyhedron> tracked_;  // one per scene shape
  std::vector<double> radius_;              // bounding radius per body
  double cell_ = 2.0;
  int cells_ = 1;
  std::vector<std::int32_t> head_, next_;  // cell lists
  std::unordered_map<std::uint64_t, Episode> episodes_;
  std::vector<bool> escaped_;
  std::uint64_t measurement_ = 0;
  ProbeTotals totals_;
};

}  // namespace sparsedyn::bench
