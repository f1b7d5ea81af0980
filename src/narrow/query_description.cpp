// SPDX-License-Identifier: MIT
// DescribeQuery: a failed closest-feature query as text to paste into a regression test.
#include <sstream>

#include "sparsedyn/narrow/closest_features.hpp"

namespace sparsedyn {
namespace {

void WritePolyhedron(std::ostringstream& out, const ConvexPolyhedron& polyhedron) {
  out << "PolygonMesh{.vertices = {";
  for (const Eigen::Vector3d& p : polyhedron.vertices()) {
    out << "{" << p.x() << ", " << p.y() << ", " << p.z() << "}, ";
  }
  out << "}, .faces = {";
  for (int f = 0; f < polyhedron.face_count(); ++f) {
    out << "{";
    for (const std::int32_t v : polyhedron.FaceVertices(f)) out << v << ", ";
    out << "}, ";
  }
  out << "}}\n";
}

void WritePose(std::ostringstream& out, const Pose& X) {
  out << "Pose{.rotation = Eigen::Quaterniond(" << X.rotation.w() << ", " << X.rotation.x() << ", "
      << X.rotation.y() << ", " << X.rotation.z() << "), .translation = {" << X.translation.x()
      << ", " << X.translation.y() << ", " << X.translation.z() << "}}\n";
}

}  // namespace

std::string DescribeQuery(const TrackedPolyhedron& a, const Pose& X_WA, const TrackedPolyhedron& b,
                          const Pose& X_WB, std::optional<FeaturePair> start) {
  std::ostringstream out;
  out.precision(17);
  out << "closest-features query\nA = ";
  WritePolyhedron(out, a.polyhedron());
  out << "X_WA = ";
  WritePose(out, X_WA);
  out << "B = ";
  WritePolyhedron(out, b.polyhedron());
  out << "X_WB = ";
  WritePose(out, X_WB);
  out << "start = ";
  if (start) {
    out << ToString(start->a) << " / " << ToString(start->b) << "\n";
  } else {
    out << "cold\n";
  }
  return out.str();
}

}  // namespace sparsedyn
