// SPDX-License-Identifier: MIT
#include "math/polynomial.hpp"

#include <cstdio>

#include "sparsedyn/assert.hpp"

namespace sparsedyn {

Polynomial::Polynomial(std::initializer_list<double> coefficients_low_to_high) {
  SPARSEDYN_ASSERT(coefficients_low_to_high.size() <= c_.size(),
                   "at most kMaxPolynomialDegree + 1 coefficients");
  int i = 0;
  for (double value : coefficients_low_to_high) c_[static_cast<std::size_t>(i++)] = value;
}

Polynomial Polynomial::FromCoefficients(const double* c, int count) {
  SPARSEDYN_ASSERT(count >= 0 && count <= kMaxPolynomialDegree + 1,
                   "at most kMaxPolynomialDegree + 1 coefficients");
  Polynomial p;
  for (int i = 0; i < count; ++i) p.c_[static_cast<std::size_t>(i)] = c[i];
  return p;
}

int Polynomial::Degree() const {
  for (int i = kMaxPolynomialDegree; i >= 0; --i) {
    if (c_[static_cast<std::size_t>(i)] != 0.0) return i;
  }
  return -1;
}

void Polynomial::SetCoefficient(int i, double value) {
  SPARSEDYN_ASSERT(i >= 0 && i <= kMaxPolynomialDegree, "coefficient index out of range");
  c_[static_cast<std::size_t>(i)] = value;
}

double Polynomial::operator()(double t) const {
  double value = 0.0;
  for (int i = Degree(); i >= 0; --i) value = value * t + c_[static_cast<std::size_t>(i)];
  return value;
}

Polynomial Polynomial::Derivative() const {
  Polynomial d;
  for (int i = 1; i <= kMaxPolynomialDegree; ++i) {
    d.c_[static_cast<std::size_t>(i - 1)] =
        static_cast<double>(i) * c_[static_cast<std::size_t>(i)];
  }
  return d;
}

Polynomial Polynomial::Shifted(double dt) const {
  // Repeated synthetic division by (t - dt): after pass k, c[k] is the k-th Taylor coefficient
  // p^(k)(dt) / k! (Knuth TAOCP vol. 2, 4.6.4).
  Polynomial q = *this;
  const int degree = Degree();
  for (int k = 0; k < degree; ++k) {
    for (int i = degree - 1; i >= k; --i) {
      q.c_[static_cast<std::size_t>(i)] += dt * q.c_[static_cast<std::size_t>(i + 1)];
    }
  }
  return q;
}

Polynomial operator+(const Polynomial& a, const Polynomial& b) {
  Polynomial sum;
  for (std::size_t i = 0; i < sum.c_.size(); ++i) sum.c_[i] = a.c_[i] + b.c_[i];
  return sum;
}

Polynomial operator-(const Polynomial& a, const Polynomial& b) {
  Polynomial difference;
  for (std::size_t i = 0; i < difference.c_.size(); ++i) difference.c_[i] = a.c_[i] - b.c_[i];
  return difference;
}

Polynomial operator*(const Polynomial& a, const Polynomial& b) {
  const int da = a.Degree();
  const int db = b.Degree();
  Polynomial product;
  if (da < 0 || db < 0) return product;
  SPARSEDYN_ASSERT(da + db <= kMaxPolynomialDegree, "product degree exceeds kMaxPolynomialDegree");
  for (int i = 0; i <= da; ++i) {
    for (int j = 0; j <= db; ++j) {
      product.c_[static_cast<std::size_t>(i + j)] +=
          a.c_[static_cast<std::size_t>(i)] * b.c_[static_cast<std::size_t>(j)];
    }
  }
  return product;
}

Polynomial Polynomial::operator*(double s) const {
  Polynomial scaled;
  for (std::size_t i = 0; i < c_.size(); ++i) scaled.c_[i] = c_[i] * s;
  return scaled;
}

Polynomial Polynomial::operator-() const {
  Polynomial negated;
  for (std::size_t i = 0; i < c_.size(); ++i) negated.c_[i] = -c_[i];
  return negated;
}

std::string Polynomial::ToString() const {
  std::string text = "Polynomial{";
  const int degree = Degree();
  for (int i = 0; i <= (degree < 0 ? 0 : degree); ++i) {
    char buffer[40];
    std::snprintf(buffer, sizeof(buffer), "%s%.17g", i == 0 ? "" : ", ",
                  c_[static_cast<std::size_t>(i)]);
    text += buffer;
  }
  return text + "}";
}

}  // namespace sparsedyn
