#include "experiments/results/spread.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include <boost/math/distributions/students_t.hpp>

namespace dvpr {

double StudentT975(int degrees_of_freedom) {
  if (degrees_of_freedom < 1) {
    throw std::invalid_argument("StudentT975: need at least 1 degree of freedom, got " +
                                std::to_string(degrees_of_freedom));
  }
  const boost::math::students_t t(static_cast<double>(degrees_of_freedom));
  return boost::math::quantile(boost::math::complement(t, 0.025));
}

Spread SpreadOf(std::span<const double> values) {
  Spread s;
  double sum = 0.0;
  for (const double v : values) {
    if (std::isnan(v)) continue;
    sum += v;
    ++s.n;
  }
  if (s.n == 0) return s;
  s.mean = sum / s.n;
  if (s.n < 2) return s;
  double squares = 0.0;
  for (const double v : values) {
    if (!std::isnan(v)) squares += (v - s.mean) * (v - s.mean);
  }
  s.std = std::sqrt(squares / (s.n - 1));
  s.ci95 = StudentT975(s.n - 1) * s.std / std::sqrt(static_cast<double>(s.n));
  return s;
}

}  // namespace dvpr
