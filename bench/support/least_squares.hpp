// SPDX-License-Identifier: MIT
// Least-squares fits for the thesis's figures (bench/scenes/thesis_figures.cpp): the straight
// line of §7.2 and the one-constant law of App. I.1, each with its coefficient of determination.
#pragma once

#include <cstddef>
#include <vector>

namespace sparsedyn::bench {

/// y = intercept + slope x, and R^2 = 1 - SS_res / SS_tot (1 when every y is equal and fitted).
struct LineFit {
  double intercept = 0;
  double slope = 0;
  double r2 = 0;
};

/// y = k x through the origin (a law with one free constant), and its R^2 against the mean of y.
struct ProportionalFit {
  double k = 0;
  double r2 = 0;
};

namespace detail {
// R^2 of a model's predictions `fitted` for `y`.
inline double RSquared(const std::vector<double>& y, const std::vector<double>& fitted) {
  double mean = 0;
  for (double v : y) mean += v;
  mean /= static_cast<double>(y.size());
  double ss_res = 0;
  double ss_tot = 0;
  for (std::size_t i = 0; i < y.size(); ++i) {
    ss_res += (y[i] - fitted[i]) * (y[i] - fitted[i]);
    ss_tot += (y[i] - mean) * (y[i] - mean);
  }
  return ss_tot > 0 ? 1 - ss_res / ss_tot : (ss_res == 0 ? 1.0 : 0.0);
}
}  // namespace detail

/// Ordinary least squares of y on x; needs at least two distinct x.
inline LineFit FitLine(const std::vector<double>& x, const std::vector<double>& y) {
  const auto n = static_cast<double>(x.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sx += x[i];
    sy += y[i];
    sxx += x[i] * x[i];
    sxy += x[i] * y[i];
  }
  LineFit fit;
  fit.slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  fit.intercept = (sy - fit.slope * sx) / n;
  std::vector<double> fitted(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) fitted[i] = fit.intercept + fit.slope * x[i];
  fit.r2 = detail::RSquared(y, fitted);
  return fit;
}

/// Least squares of y = k x: k = sum(x y) / sum(x^2).
inline ProportionalFit FitProportional(const std::vector<double>& x, const std::vector<double>& y) {
  double sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sxx += x[i] * x[i];
    sxy += x[i] * y[i];
  }
  ProportionalFit fit;
  fit.k = sxy / sxx;
  std::vector<double> fitted(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) fitted[i] = fit.k * x[i];
  fit.r2 = detail::RSquared(y, fitted);
  return fit;
}

}  // namespace sparsedyn::bench
