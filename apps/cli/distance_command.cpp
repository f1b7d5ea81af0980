// SPDX-License-Identifier: MIT
#include "apps/cli/distance_command.hpp"

#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "sparsedyn/geometry/convex_polyhedron.hpp"
#include "sparsedyn/io/distance_summary.hpp"
#include "sparsedyn/io/mesh_io.hpp"
#include "sparsedyn/narrow/closest_features.hpp"

namespace sparsedyn::cli {
namespace {

// A quaternion is accepted when its norm is within this of 1 and then normalised: files and
// scripts print 6-9 digits, which leaves a norm of 1 +- 1e-7 or so; anything farther from unit
// length is a mistake (a zero quaternion, swapped fields), not round-off, and is refused.
constexpr double kUnitQuaternionTolerance = 1e-6;

struct DistanceOptions {
  std::string file_a, file_b;
  std::vector<double> pose_a, pose_b;  // empty or x y z qw qx qy qz
  bool json = false;
};

Result<Pose> ParsePose(const std::vector<double>& values, const char* option) {
  Pose pose;
  if (values.empty()) return pose;
  for (const double v : values) {
    if (!std::isfinite(v)) {
      return Error{std::string(option) + ": every value must be finite"};
    }
  }
  pose.translation = {values[0], values[1], values[2]};
  const Eigen::Quaterniond q(values[3], values[4], values[5], values[6]);
  const double norm = q.norm();
  if (std::abs(norm - 1.0) > kUnitQuaternionTolerance) {
    std::ostringstream message;
    message << option
            << ": the quaternion (qw qx qy qz) must have unit norm (within 1e-6), got norm ";
    message.precision(17);
    message << norm;
    return Error{message.str()};
  }
  pose.rotation = q.normalized();
  return pose;
}

Result<std::shared_ptr<const ConvexPolyhedron>> LoadPolyhedron(const std::string& path) {
  Result<PolygonMesh> mesh = ReadMesh(path);
  if (!mesh) return mesh.error();
  Result<ConvexPolyhedron> polyhedron = ConvexPolyhedron::FromMesh(*mesh);
  if (!polyhedron) return Error{path + ": " + polyhedron.error().message};
  for (const std::string& warning : polyhedron->warnings()) {
    std::cerr << "sparsedyn distance: warning: " << path << ": " << warning << "\n";
  }
  return std::make_shared<const ConvexPolyhedron>(std::move(*polyhedron));
}

int Distance(const DistanceOptions& options) {
  auto fail = [](const std::string& message) {
    std::cerr << "sparsedyn distance: " << message << "\n";
    return 2;
  };
  const Result<Pose> X_WA = ParsePose(options.pose_a, "--pose-a");
  if (!X_WA) return fail(X_WA.error().message);
  const Result<Pose> X_WB = ParsePose(options.pose_b, "--pose-b");
  if (!X_WB) return fail(X_WB.error().message);
  auto a = LoadPolyhedron(options.file_a);
  if (!a) return fail(a.error().message);
  auto b = LoadPolyhedron(options.file_b);
  if (!b) return fail(b.error().message);

  const TrackedPolyhedron tracked_a(*a), tracked_b(*b);
  const ClosestFeatures r = FindClosestFeatures(tracked_a, *X_WA, tracked_b, *X_WB);
  if (options.json) {
    std::cout << nlohmann::json::parse(DistanceSummaryJson(r)).dump(2) << "\n";
  } else {
    std::printf("%s: distance %.17g\n", StatusName(r.status), r.distance);
    std::printf("  A %s: %s, closest point (%.17g, %.17g, %.17g)\n", options.file_a.c_str(),
                ToString(r.features.a).c_str(), r.point_a.x(), r.point_a.y(), r.point_a.z());
    std::printf("  B %s: %s, closest point (%.17g, %.17g, %.17g)\n", options.file_b.c_str(),
                ToString(r.features.b).c_str(), r.point_b.x(), r.point_b.y(), r.point_b.z());
    std::printf("  normal from A to B (%.17g, %.17g, %.17g), %d walk steps\n", r.normal.x(),
                r.normal.y(), r.normal.z(), r.steps);
  }
  if (r.status == ClosestFeatures::Status::kIterationCap) {
    std::cerr << "sparsedyn distance: the closest-feature walk hit its iteration cap ("
              << ClosestFeaturesOptions{}.max_steps << " steps): the result is not final\n";
    return 1;
  }
  return 0;
}

}  // namespace

void AddDistanceCommand(CLI::App& app) {
  auto options = std::make_shared<DistanceOptions>();
  CLI::App* distance = app.add_subcommand(
      "distance", "Closest features and signed distance of two convex polyhedra (mesh files)");
  distance->add_option("A", options->file_a, "Mesh file of A (OFF, OBJ, STL, PLY, Ohio)")
      ->required();
  distance->add_option("B", options->file_b, "Mesh file of B")->required();
  distance
      ->add_option("--pose-a", options->pose_a, "Pose of A: x y z qw qx qy qz (unit quaternion)")
      ->expected(7);
  distance->add_option("--pose-b", options->pose_b, "Pose of B: x y z qw qx qy qz")->expected(7);
  distance->add_flag("--json", options->json, "Print one JSON object on stdout");
  distance->callback([options] { throw CLI::RuntimeError(Distance(*options)); });
}

}  // namespace sparsedyn::cli
