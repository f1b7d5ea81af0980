// SPDX-License-Identifier: MIT
// AllPairs: every other element at each image (27 in a periodic box, one elsewhere), and the
// nearest image's index against a brute-force minimum over the 27.
#include "broadphase/all_pairs.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <set>
#include <utility>
#include <vector>

#include "scenes/random.hpp"

namespace sparsedyn {
namespace {

TEST(AllPairs, VisitsEveryOtherElementAtEveryImage) {
  for (const bool periodic : {false, true}) {
    AllPairs all(AllPairs::Config{Vec3::Zero(), Vec3(4, 5, 6), periodic}, 5);
    for (std::uint32_t e = 0; e < 5; ++e) all.Insert(e, Vec3::Zero());
    all.Insert(2, Vec3::Zero());  // twice: still one member
    const std::size_t images = periodic ? 27 : 1;
    ASSERT_EQ(all.ImageShifts().size(), images);
    // The documented order (MeetingScan::ConsiderImages' slabs rely on it): x fastest.
    for (std::size_t r = 0; r < images && periodic; ++r) {
      const Vec3 expected((static_cast<double>(r % 3) - 1) * 4,
                          (static_cast<double>(r / 3 % 3) - 1) * 5,
                          (static_cast<double>(r / 9) - 1) * 6);
      EXPECT_EQ(all.ImageShifts()[r], expected) << "image " << r;
      // Its steps' shifts along each axis are its components.
      const std::array<Vec3, 3> steps = all.StepShifts();
      EXPECT_EQ(steps[r % 3][0], expected[0]) << "image " << r;
      EXPECT_EQ(steps[r / 3 % 3][1], expected[1]) << "image " << r;
      EXPECT_EQ(steps[r / 9][2], expected[2]) << "image " << r;
    }
    std::multiset<std::uint32_t> seen;
    std::set<std::pair<std::uint32_t, std::uint32_t>> shifted;  // (j, image index)
    all.ForEachNeighbor(3, [&](std::uint32_t j, const Vec3& shift) {
      seen.insert(j);
      for (std::size_t r = 0; r < images; ++r) {
        if (all.ImageShifts()[r] == shift) shifted.emplace(j, r);
      }
    });
    EXPECT_EQ(seen.count(3), 0u);
    for (const std::uint32_t j : {0u, 1u, 2u, 4u}) EXPECT_EQ(seen.count(j), images);
    EXPECT_EQ(shifted.size(), 4 * images);  // each image once, and only the listed ones
    std::vector<std::uint32_t> others;
    all.ForEachOther(3, [&](std::uint32_t j) { others.push_back(j); });
    EXPECT_EQ(others, (std::vector<std::uint32_t>{0, 1, 2, 4}));
    EXPECT_EQ(all.LargestShift(), periodic ? Vec3(4, 5, 6) : Vec3::Zero());
  }
}

TEST(AllPairs, NearestImageIsTheBruteForceMinimum) {
  const Vec3 hi(4, 5, 6);
  AllPairs all(AllPairs::Config{Vec3::Zero(), hi, true}, 0);
  const std::vector<Vec3>& shifts = all.ImageShifts();
  scenes::Random random(20261128);
  for (int trial = 0; trial < 2000; ++trial) {
    // Two points in the box: their difference is within one length along every axis.
    const Vec3 a(random.Uniform(0, hi[0]), random.Uniform(0, hi[1]), random.Uniform(0, hi[2]));
    const Vec3 b(random.Uniform(0, hi[0]), random.Uniform(0, hi[1]), random.Uniform(0, hi[2]));
    const Vec3 d = b - a;
    std::size_t best = 0;
    for (std::size_t r = 1; r < shifts.size(); ++r) {
      if ((d + shifts[r]).norm() < (d + shifts[best]).norm()) best = r;
    }
    ASSERT_EQ(all.NearestImage(d), best) << "d = " << d.transpose();
    for (int k = 0; k < 3; ++k) EXPECT_LE(std::abs(d[k] + shifts[best][k]), 0.5 * hi[k]);
  }
  AllPairs open(AllPairs::Config{Vec3::Zero(), hi, false}, 0);
  EXPECT_EQ(open.NearestImage(Vec3(3.9, -4.9, 5.9)), 0u);
}

}  // namespace
}  // namespace sparsedyn
