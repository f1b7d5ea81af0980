// SPDX-License-Identifier: MIT
#include "world/support_polygon.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <Eigen/Geometry>

namespace sparsedyn {

void OrderAroundMean(std::vector<Vec3>& points, const Vec3& n) {
  if (points.size() < 3) return;
  const Vec3 mean = std::accumulate(points.begin(), points.end(), Vec3(Vec3::Zero())) /
                    static_cast<double>(points.size());
  const Vec3 u = n.unitOrthogonal();
  const Vec3 v = n.cross(u);
  std::sort(points.begin(), points.end(), [&](const Vec3& p, const Vec3& q) {
    return std::atan2((p - mean).dot(v), (p - mean).dot(u)) <
           std::atan2((q - mean).dot(v), (q - mean).dot(u));
  });
}

bool OverPolygon(const std::vector<Vec3>& points, const Vec3& c, const Vec3& n) {
  int positive = 0, negative = 0;
  for (std::size_t k = 0; k < points.size(); ++k) {
    const Vec3& a = points[k];
    const Vec3& b = points[(k + 1) % points.size()];
    const double turn = n.dot((b - a).cross(c - a));
    positive += turn > 0 ? 1 : 0;
    negative += turn < 0 ? 1 : 0;
  }
  const int n_points = static_cast<int>(points.size());
  return positive == n_points || negative == n_points;
}

}  // namespace sparsedyn
