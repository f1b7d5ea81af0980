// SPDX-License-Identifier: MIT
#include "sparsedyn/result.hpp"

#include <gtest/gtest.h>

namespace sparsedyn {
namespace {

TEST(Result, HoldsValueOrError) {
  Result<int> good = 3;
  ASSERT_TRUE(good.ok());
  EXPECT_EQ(*good, 3);
  Result<int> bad = Error{"body 2: mass must be > 0, got 0"};
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.error().message, "body 2: mass must be > 0, got 0");
}

TEST(Status, DefaultIsOk) {
  EXPECT_TRUE(Status::Ok().ok());
  Status failed = Error{"x"};
  EXPECT_FALSE(failed.ok());
}

}  // namespace
}  // namespace sparsedyn
