#include "net_models/param_checks.h"

#include <sstream>

namespace dvpr {

void InvalidParam(std::string_view field, const std::string& problem) {
  throw std::invalid_argument(std::string(field) + ": " + problem);
}

void CheckProbability(std::string_view field, double p) {
  if (p >= 0.0 && p <= 1.0) return;
  std::ostringstream got;
  got << p;
  InvalidParam(field, "a probability must lie in [0, 1], got " + got.str());
}

void CheckPositiveRate(std::string_view field, DataRate rate) {
  if (rate.bps() <= 0) InvalidParam(field, "a data rate must be positive, got " + std::to_string(rate.bps()) + "bps");
}

void CheckNonNegativeDuration(std::string_view field, SimTime t) {
  if (t < SimTime::Zero()) InvalidParam(field, "must not be negative, got " + std::to_string(t.ns()) + "ns");
}

void CheckNonNegativeCount(std::string_view field, std::int64_t n) {
  if (n < 0) InvalidParam(field, "must not be negative, got " + std::to_string(n));
}

}  // namespace dvpr
