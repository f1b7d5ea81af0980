// SPDX-License-Identifier: MIT
#include "bench/peers/thesis/contact_probe.hpp"

#include <algorithm>
#include <cmath>

namespace sparsedyn::bench {

ContactProbe::ContactProbe(const SceneDescription& scene) : scene_(scene) {
  tracked_.reserve(scene.shapes.size());
  for (const SceneShape& shape : scene.shapes) tracked_.emplace_back(shape.polyhedron);
  double largest = 0;
  for (const SceneBody& body : scene.bodies) {
    radius_.push_back(scene.shapes[body.shape].radius);
    largest = std::max(largest, radius_.back());
  }
  // Cells one largest diameter wide: overlapping spheres are in the same or adjacent cells.
  const Vec3 size = scene.settings.container.hi - scene.settings.container.lo;
  cell_ = 2 * largest;
  cells_ = std::max(1, static_cast<int>(size.maxCoeff() / cell_));
  cell_ = std::max(cell_, size.maxCoeff() / cells_);
  head_.assign(static_cast<std::size_t>(cells_) * cells_ * cells_, -1);
  next_.assign(scene.bodies.size(), -1);
  escaped_.assign(scene.bodies.size(), false);
}

void ContactProbe::Measure(std::span<const Pose> X_WB) {
  ++measurement_;
  FindPairs(X_WB);

  // Episodes whose pair was not found this time have ended.
  for (auto it = episodes_.begin(); it != episodes_.end();) {
    if (it->second.seen == measurement_) {
      ++it;
      continue;
    }
    EndEpisode(it->second);
    it = episodes_.erase(it);
  }

  // Walls: a body whose sphere crosses one may penetrate it; a centre outside escaped.
  const Container& box = scene_.settings.container;
  for (std::uint32_t i = 0; i < X_WB.size(); ++i) {
    const Vec3& p = X_WB[i].translation;
    const double r = radius_[i];
    if (((p.array() - r) < box.lo.array()).any() || ((p.array() + r) > box.hi.array()).any()) {
      MeasureWalls(i, X_WB[i]);
    }
    if (!escaped_[i] &&
        (((p.array() < box.lo.array())).any() || (p.array() > box.hi.array()).any())) {
      escaped_[i] = true;
      ++totals_.escaped;
    }
  }
}

void ContactProbe::FindPairs(std::span<const Pose> X_WB) {
  const Vec3& lo = scene_.settings.container.lo;
  auto cell_of = [&](const Vec3& p, int k) {
    return std::clamp(static_cast<int>(std::floor((p[k] - lo[k]) / cell_)), 0, cells_ - 1);
  };
  auto index = [&](int x, int y, int z) {
    return (static_cast<std::size_t>(z) * cells_ + y) * cells_ + x;
  };
  std::fill(head_.begin(), head_.end(), -1);
  for (std::uint32_t i = 0; i < X_WB.size(); ++i) {
    const Vec3& p = X_WB[i].translation;
    std::int32_t& head = head_[index(cell_of(p, 0), cell_of(p, 1), cell_of(p, 2))];
    next_[i] = head;
    head = static_cast<std::int32_t>(i);
  }

  // Every body against the bodies of higher index in its own and the 26 adjacent cells.
  for (std::uint32_t a = 0; a < X_WB.size(); ++a) {
    const Vec3& p = X_WB[a].translation;
    const int cx = cell_of(p, 0), cy = cell_of(p, 1), cz = cell_of(p, 2);
    for (int z = std::max(0, cz - 1); z <= std::min(cells_ - 1, cz + 1); ++z) {
      for (int y = std::max(0, cy - 1); y <= std::min(cells_ - 1, cy + 1); ++y) {
        for (int x = std::max(0, cx - 1); x <= std::min(cells_ - 1, cx + 1); ++x) {
          for (std::int32_t b = head_[index(x, y, z)]; b >= 0; b = next_[b]) {
            const auto ub = static_cast<std::uint32_t>(b);
            if (ub <= a) continue;
            const double reach = radius_[a] + radius_[ub];
            if ((X_WB[ub].translation - p).squaredNorm() < reach * reach) {
              MeasurePair(a, ub, X_WB);
            }
          }
        }
      }
    }
  }
}

void ContactProbe::MeasurePair(std::uint32_t a, std::uint32_t b, std::span<const Pose> X_WB) {
  const std::uint64_t key = (static_cast<std::uint64_t>(a) << 32) | b;
  const Eigen::Vector3d d = X_WB[b].translation - X_WB[a].translation;
  auto [it, is_new] = episodes_.try_emplace(key);
  Episode& episode = it->second;
  if (is_new) episode.d0 = d;
  episode.d = d;
  episode.seen = measurement_;

  const ClosestFeatures found =
      FindClosestFeatures(tracked_[scene_.bodies[a].shape], X_WB[a],
                          tracked_[scene_.bodies[b].shape], X_WB[b], episode.warm);
  ++totals_.queries;
  if (found.status == ClosestFeatures::Status::kIterationCap) {
    ++totals_.iteration_caps;
    episode.warm.reset();
    return;
  }
  episode.warm = found.features;
  const double smaller = std::min(radius_[a], radius_[b]);
  if (found.distance < kTouchFraction * smaller && !episode.touched) {
    episode.touched = true;
    ++totals_.contacts;
  }
  if (found.distance >= 0) return;
  const double depth = -found.distance;
  totals_.max_penetration = std::max(totals_.max_penetration, depth);
  if (!episode.overlapped) ++totals_.penetrating;
  episode.overlapped = true;
  const double deep = kDeepPenetrationFraction * smaller;
  if (depth > deep && !episode.deep) ++totals_.deep_contacts;
  if (depth > deep) episode.deep = true;
}

void ContactProbe::MeasureWalls(std::uint32_t i, const Pose& X_WB) {
  const Container& box = scene_.settings.container;
  double depth = 0;
  for (const Eigen::Vector3d& p_B : tracked_[scene_.bodies[i].shape].polyhedron().vertices()) {
    const Eigen::Vector3d p_W = X_WB.ToWorld(p_B);
    depth = std::max({depth, (box.lo - p_W).maxCoeff(), (p_W - box.hi).maxCoeff()});
  }
  totals_.max_penetration = std::max(totals_.max_penetration, depth);
}

void ContactProbe::EndEpisode(const Episode& episode) {
  if (episode.overlapped && episode.d0.dot(episode.d) < 0) ++totals_.passed_through;
}

const ProbeTotals& ContactProbe::Finish() {
  for (const auto& [key, episode] : episodes_) EndEpisode(episode);
  episodes_.clear();
  return totals_;
}

}  // namespace sparsedyn::bench
