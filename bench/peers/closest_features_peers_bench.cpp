// SPDX-License-Identifier: MIT
// The §7.3 feature-tracking experiment (thesis App. J.2) with the peers in the same process, on
// the same precomputed poses: our warm-started ClosestFeatureTracker, FCL 0.7 distance with
// libccd's GJK (GST_LIBCCD) and with FCL's own GJK (GST_INDEP), and Bullet 3.24's
// btGjkPairDetector (double precision, collision margins set to 0). Before timing, every engine's
// distance is compared with ours at every pose and with a brute-force distance on a sample of
// poses; the largest disagreements are printed and reported as the counters `max_dev` and
// `max_dev_brute` (absolute; both polyhedra have bounding radius 1, gaps are about 0.5).
//
// Each engine is used in the plain way for repeated distance queries of one pair:
// FCL gets fresh request/result objects per query (its API keeps no state between queries);
// Bullet keeps one btGjkPairDetector per pair, which warm-starts from its cached separating
// axis. Pose conversion to each engine's types is done once, outside the timed loop.
#include <BulletCollision/CollisionShapes/btConvexHullShape.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkEpaPenetrationDepthSolver.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkPairDetector.h>
#include <BulletCollision/NarrowPhaseCollision/btPointCollector.h>
#include <BulletCollision/NarrowPhaseCollision/btVoronoiSimplexSolver.h>
#include <benchmark/benchmark.h>
#include <fcl/geometry/shape/convex.h>
#include <fcl/narrowphase/distance.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "bench/support/brute_force_distance.hpp"
#include "bench/support/closest_features_cases.hpp"

namespace sparsedyn::bench {
namespace {

// ---------------------------------------------------------------------------------------------
// Conversions to the peers' types (done once per case).

std::shared_ptr<fcl::Convexd> ToFcl(const ConvexPolyhedron& polyhedron) {
  auto vertices = std::make_shared<std::vector<fcl::Vector3d>>(polyhedron.vertices().begin(),
                                                               polyhedron.vertices().end());
  // FCL's face encoding: vertex count, then the vertex indices, counter-clockwise from outside.
  auto faces = std::make_shared<std::vector<int>>();
  for (int f = 0; f < polyhedron.face_count(); ++f) {
    const auto loop = polyhedron.FaceVertices(f);
    faces->push_back(static_cast<int>(loop.size()));
    faces->insert(faces->end(), loop.begin(), loop.end());
  }
  return std::make_shared<fcl::Convexd>(vertices, polyhedron.face_count(), faces,
                                        /*throw_if_invalid=*/true);
}

fcl::Transform3d ToFcl(const Pose& X) {
  fcl::Transform3d T = fcl::Transform3d::Identity();
  T.linear() = X.rotation.toRotationMatrix();
  T.translation() = X.translation;
  return T;
}

// Margin 0: Bullet then reports the distance between the hulls themselves, like FCL and us.
std::unique_ptr<btConvexHullShape> ToBullet(const ConvexPolyhedron& polyhedron) {
  auto shape = std::make_unique<btConvexHullShape>();
  for (const Eigen::Vector3d& v : polyhedron.vertices()) {
    shape->addPoint(btVector3(v.x(), v.y(), v.z()), /*recalculateLocalAabb=*/false);
  }
  shape->recalcLocalAabb();
  shape->setMargin(0.0);
  return shape;
}

btTransform ToBullet(const Pose& X) {
  const Eigen::Quaterniond& q = X.rotation;
  return btTransform(btQuaternion(q.x(), q.y(), q.z(), q.w()),
                     btVector3(X.translation.x(), X.translation.y(), X.translation.z()));
}

// One case in every engine's types.
struct PeerCase {
  const ClosestFeaturesCase* base = nullptr;
  std::shared_ptr<fcl::Convexd> fcl_a, fcl_b;
  std::vector<fcl::Transform3d> fcl_X_WA;
  fcl::Transform3d fcl_X_WB;
  std::unique_ptr<btConvexHullShape> bullet_a, bullet_b;
  std::vector<btTransform> bullet_X_WA;
  btTransform bullet_X_WB;
  // Largest |distance - reference| by engine name: against kReference at every pose, and
  // against brute force on a sample of poses.
  std::map<std::string, double> max_dev, max_dev_brute;
};

std::unique_ptr<PeerCase> MakePeerCase(const ClosestFeaturesCase& c) {
  auto p = std::make_unique<PeerCase>();
  p->base = &c;
  p->fcl_a = ToFcl(*c.pair.a);
  p->fcl_b = ToFcl(*c.pair.b);
  p->fcl_X_WB = ToFcl(c.pair.X_WB);
  p->bullet_a = ToBullet(*c.pair.a);
  p->bullet_b = ToBullet(*c.pair.b);
  p->bullet_X_WB = ToBullet(c.pair.X_WB);
  for (const Pose& X_WA : c.pair.X_WA) {
    p->fcl_X_WA.push_back(ToFcl(X_WA));
    p->bullet_X_WA.push_back(ToBullet(X_WA));
  }
  return p;
}

// ---------------------------------------------------------------------------------------------
// The peers, each answering "distance at pose k".

class FclEngine {
 public:
  FclEngine(const PeerCase& c, fcl::GJKSolverType solver) : c_(c) {
    request_.gjk_solver_type = solver;
    request_.enable_nearest_points = true;  // we return witness points too
  }
  double Distance(std::size_t k) const {
    fcl::DistanceResultd result;
    fcl::distance(c_.fcl_a.get(), c_.fcl_X_WA[k], c_.fcl_b.get(), c_.fcl_X_WB, request_, result);
    return result.min_distance;
  }

 private:
  const PeerCase& c_;
  fcl::DistanceRequestd request_;
};

class BulletEngine {
 public:
  explicit BulletEngine(const PeerCase& c)
      : c_(c), detector_(c.bullet_a.get(), c.bullet_b.get(), &simplex_, &penetration_) {}
  double Distance(std::size_t k) {
    btGjkPairDetector::ClosestPointInput input;
    input.m_transformA = c_.bullet_X_WA[k];
    input.m_transformB = c_.bullet_X_WB;
    btPointCollector output;
    detector_.getClosestPoints(input, output, nullptr);
    return output.m_distance;
  }

 private:
  const PeerCase& c_;
  btVoronoiSimplexSolver simplex_;
  btGjkEpaPenetrationDepthSolver penetration_;
  btGjkPairDetector detector_;
};

// Engine names as they appear in benchmark names, the CSV and the plot.
constexpr const char* kFclLibccd = "fcl_libccd";
constexpr const char* kFclIndep = "fcl_indep";
constexpr const char* kBullet = "bullet_gjk";

// Every peer's distances over one lap of the case's poses.
std::map<std::string, std::vector<double>> PeerDistances(const PeerCase& c) {
  std::map<std::string, std::vector<double>> distances;
  const FclEngine libccd(c, fcl::GST_LIBCCD), indep(c, fcl::GST_INDEP);
  BulletEngine bullet(c);
  for (std::size_t k = 0; k < c.fcl_X_WA.size(); ++k) {
    distances[kFclLibccd].push_back(libccd.Distance(k));
    distances[kFclIndep].push_back(indep.Distance(k));
    distances[kBullet].push_back(bullet.Distance(k));
  }
  return distances;
}

// ---------------------------------------------------------------------------------------------
// Benchmarks.

template <typename Engine, typename... Args>
void BM_Peer(benchmark::State& state, const PeerCase* c, const char* name, Args... args) {
  Engine engine(*c, args...);
  const std::size_t n = c->fcl_X_WA.size();
  for (std::size_t k = 0; k < n; ++k) benchmark::DoNotOptimize(engine.Distance(k));
  std::size_t k = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(engine.Distance(k));
    if (++k == n) k = 0;
  }
  SetCaseCounters(state, *c->base);
  state.counters["max_dev"] = c->max_dev.at(name);
  state.counters["max_dev_brute"] = c->max_dev_brute.at(name);
}

// This many poses per case are checked against the brute-force distance (O(V F + E^2) per pose,
// about 25 ms at 1000 faces).
constexpr std::size_t kBruteForcePoses = 40;

// The engine every other is compared with at every pose.
constexpr const char* kReference = "ours";

// Pose indices for the brute-force check, spread over the loop but not at the same spin angles
// for every angle per step (a plain stride would give identical poses for 1°, 5° and 25°).
std::vector<std::size_t> SamplePoses(std::size_t n) {
  std::vector<std::size_t> poses;
  for (std::size_t j = 0; j < std::min(n, kBruteForcePoses); ++j) {
    poses.push_back((j * n / kBruteForcePoses + j * 7919) % n);
  }
  return poses;
}

// Compares every engine with the brute-force distance on a sample of poses and with the reference
// engine at every pose; prints one line per case and keeps the largest absolute disagreements in
// the case.
void CheckAgreement(PeerCase& c) {
  const scenes::RotatingPair& pair = c.base->pair;
  std::map<std::string, std::vector<double>> distances = PeerDistances(c);
  distances["ours"] = OursDistances(*c.base);
  const std::vector<double>& reference = distances.at(kReference);
  std::vector<std::pair<std::size_t, double>> brute;
  double min_gap = std::numeric_limits<double>::infinity();
  for (const std::size_t k : SamplePoses(pair.X_WA.size())) {
    brute.emplace_back(k, BruteForceDistance(*pair.a, pair.X_WA[k], *pair.b, pair.X_WB));
    min_gap = std::min(min_gap, brute.back().second);
  }
  std::fprintf(stderr, "agreement%-18s sampled gap >= %.3f; max|d - d_brute| (max|d - d_%s|):",
               CaseName("", *c.base).c_str(), min_gap, kReference);
  for (const auto& [name, d] : distances) {
    double dev_brute = 0.0, dev_reference = 0.0;
    for (const auto& [k, b] : brute) dev_brute = std::max(dev_brute, std::abs(d[k] - b));
    for (std::size_t k = 0; k < d.size(); ++k) {
      dev_reference = std::max(dev_reference, std::abs(d[k] - reference[k]));
    }
    c.max_dev[name] = dev_reference;
    c.max_dev_brute[name] = dev_brute;
    std::fprintf(stderr, "  %s %.1e (%.1e)", name.c_str(), dev_brute, dev_reference);
  }
  std::fprintf(stderr, "\n");
}

// Cases live until the program ends; benchmarks keep raw pointers to them.
struct Registry {
  std::vector<std::unique_ptr<ClosestFeaturesCase>> cases;
  std::vector<std::unique_ptr<PeerCase>> peer_cases;
};

// Registers, per case, ours and the three peers one after the other, so that machine noise
// hits neighbouring rows alike and the ratios stay meaningful.
void RegisterAll(Registry& registry) {
  for (const int faces : kFaceCounts) {
    for (const double degrees : kDegreesPerStep) {
      const ClosestFeaturesCase* c =
          registry.cases.emplace_back(MakeClosestFeaturesCase(faces, degrees)).get();
      PeerCase* p = registry.peer_cases.emplace_back(MakePeerCase(*c)).get();
      CheckAgreement(*p);
      benchmark::RegisterBenchmark(CaseName("ours_warm", *c).c_str(), BM_OursWarm, c);
      benchmark::RegisterBenchmark(CaseName(kFclLibccd, *c).c_str(),
                                   BM_Peer<FclEngine, fcl::GJKSolverType>, p, kFclLibccd,
                                   fcl::GST_LIBCCD);
      benchmark::RegisterBenchmark(CaseName(kFclIndep, *c).c_str(),
                                   BM_Peer<FclEngine, fcl::GJKSolverType>, p, kFclIndep,
                                   fcl::GST_INDEP);
      benchmark::RegisterBenchmark(CaseName(kBullet, *c).c_str(), BM_Peer<BulletEngine>, p,
                                   kBullet);
      if (degrees == kColdStartDegrees) {
        benchmark::RegisterBenchmark(CaseName("ours_cold_table", *c).c_str(), BM_OursCold, c, true);
        benchmark::RegisterBenchmark(CaseName("ours_cold_plain", *c).c_str(), BM_OursCold, c,
                                     false);
      }
    }
  }
}

}  // namespace
}  // namespace sparsedyn::bench

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  sparsedyn::bench::Registry registry;
  sparsedyn::bench::RegisterAll(registry);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
