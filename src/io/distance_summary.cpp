// SPDX-License-Identifier: MIT
// The one summary of a closest-feature query, shared by `sparsedyn distance --json` and Python.
#include "sparsedyn/io/distance_summary.hpp"

#include <nlohmann/json.hpp>

namespace sparsedyn {

const char* StatusName(ClosestFeatures::Status status) {
  switch (status) {
    case ClosestFeatures::Status::kSeparated:
      return "separated";
    case ClosestFeatures::Status::kPenetrating:
      return "penetrating";
    case ClosestFeatures::Status::kIterationCap:
      break;
  }
  return "iteration cap";
}

std::string DistanceSummaryJson(const ClosestFeatures& r) {
  const auto vector = [](const Eigen::Vector3d& v) { return nlohmann::json{v.x(), v.y(), v.z()}; };
  const nlohmann::json out = {
      {"distance", r.distance},
      {"status", StatusName(r.status)},
      {"point_a", vector(r.point_a)},
      {"point_b", vector(r.point_b)},
      {"normal", vector(r.normal)},
      {"feature_a", ToString(r.features.a)},
      {"feature_b", ToString(r.features.b)},
      {"steps", r.steps},
  };
  return out.dump();
}

}  // namespace sparsedyn
