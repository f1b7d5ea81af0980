// SPDX-License-Identifier: MIT
#include "math/polynomial.hpp"

#include <gtest/gtest.h>

namespace sparsedyn {
namespace {

TEST(Polynomial, DefaultIsTheZeroPolynomialOfDegreeMinusOne) {
  const Polynomial p;
  EXPECT_EQ(p.Degree(), -1);
  EXPECT_EQ(p(3.0), 0.0);
  EXPECT_EQ(p.Coefficient(0), 0.0);
}

TEST(Polynomial, DegreeIsTheHighestNonZeroCoefficientEvenIfTiny) {
  EXPECT_EQ((Polynomial{1, 2, 0}).Degree(), 1);
  EXPECT_EQ((Polynomial{1, 2, 1e-300}).Degree(), 2);
  EXPECT_EQ((Polynomial{0, 0, 0, 0, 0, 0, 0, 0, 5}).Degree(), 8);
  EXPECT_EQ((Polynomial{7}).Degree(), 0);
}

TEST(Polynomial, CoefficientBeyondTheDegreeOrRangeIsZero) {
  const Polynomial p{1, 2, 3};
  EXPECT_EQ(p.Coefficient(2), 3.0);
  EXPECT_EQ(p.Coefficient(5), 0.0);
  EXPECT_EQ(p.Coefficient(-1), 0.0);
  EXPECT_EQ(p.Coefficient(kMaxPolynomialDegree + 1), 0.0);
}

TEST(Polynomial, FromCoefficientsAndSetCoefficientBuildTheSamePolynomial) {
  const double c[] = {1.5, -2.0, 0.25};
  Polynomial q;
  q.SetCoefficient(0, 1.5);
  q.SetCoefficient(1, -2.0);
  q.SetCoefficient(2, 0.25);
  EXPECT_EQ(Polynomial::FromCoefficients(c, 3), q);
}

TEST(Polynomial, HornerEvaluatesExactlyOnSmallIntegers) {
  const Polynomial p{-6, 11, -6, 1};  // (t - 1)(t - 2)(t - 3)
  EXPECT_EQ(p(1.0), 0.0);
  EXPECT_EQ(p(2.0), 0.0);
  EXPECT_EQ(p(4.0), 6.0);
  EXPECT_EQ(p(0.0), -6.0);
}

TEST(Polynomial, DerivativeMultipliesByThePower) {
  EXPECT_EQ((Polynomial{5, 3, 2, 1}).Derivative(), (Polynomial{3, 4, 3}));
  EXPECT_EQ((Polynomial{5}).Derivative(), Polynomial{});
}

TEST(Polynomial, ShiftedEvaluatesAtTheShiftedTime) {
  const Polynomial p{1, -3, 0.5, 2, -1};
  const Polynomial q = p.Shifted(1.5);
  for (double t : {-2.0, -0.5, 0.0, 0.75, 3.0}) {
    EXPECT_NEAR(q(t), p(t + 1.5), 1e-12 * (1 + std::abs(p(t + 1.5))));
  }
  // Exact on integers: (t + 1)^2 shifted by -1 is t^2.
  EXPECT_EQ((Polynomial{1, 2, 1}).Shifted(-1.0), (Polynomial{0, 0, 1}));
}

TEST(Polynomial, ArithmeticMatchesPointwiseArithmetic) {
  const Polynomial a{1, 2, 3};
  const Polynomial b{-1, 0, 0, 4};
  for (double t : {-1.5, 0.0, 2.0}) {
    EXPECT_DOUBLE_EQ((a + b)(t), a(t) + b(t));
    EXPECT_DOUBLE_EQ((a - b)(t), a(t) - b(t));
    EXPECT_DOUBLE_EQ((a * b)(t), a(t) * b(t));
    EXPECT_DOUBLE_EQ((a * 2.5)(t), 2.5 * a(t));
    EXPECT_DOUBLE_EQ((2.5 * a)(t), 2.5 * a(t));
    EXPECT_DOUBLE_EQ((-a)(t), -a(t));
  }
  EXPECT_EQ((a * b).Degree(), 5);
  EXPECT_EQ((a * Polynomial{}).Degree(), -1);
}

TEST(Polynomial, ToStringIsPasteableWith17Digits) {
  EXPECT_EQ((Polynomial{0.1, -2, 0, 1e-300}).ToString(),  // 1e-300 needs only 1 digit
            "Polynomial{0.10000000000000001, -2, 0, 1e-300}");
  EXPECT_EQ(Polynomial{}.ToString(), "Polynomial{0}");
}

}  // namespace
}  // namespace sparsedyn
