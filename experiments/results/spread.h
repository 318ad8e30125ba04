#pragma once
// The spread of a metric over a group's runs (summary.json, the printed summary table): the mean,
// the sample standard deviation and the half-width of the 95 % confidence interval of the mean
// with Student's t at n - 1 degrees of freedom - the runs are few (10 in the paper's protocol,
// often 1 to 3 here), where the normal 1.96 would be far too narrow (t = 4.30 at 3 runs).
#include <limits>
#include <span>

namespace dvpr {

struct Spread {
  int n = 0;  // the values that count (NaN ones are left out: a metric a run does not have)
  double mean = std::numeric_limits<double>::quiet_NaN();
  double std = std::numeric_limits<double>::quiet_NaN();   // sample (n - 1); NaN below 2 values
  double ci95 = std::numeric_limits<double>::quiet_NaN();  // t(0.975, n - 1) std / sqrt(n); NaN below 2
};

// Sums in the order given, so the mean is bit for bit sum / n as summary.json always wrote it.
Spread SpreadOf(std::span<const double> values);

// Student's t quantile t(0.975, degrees_of_freedom) (Boost.Math); degrees_of_freedom >= 1.
double StudentT975(int degrees_of_freedom);

}  // namespace dvpr
