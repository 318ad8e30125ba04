#include "net_models/core/param_checks.h"

#include <charconv>
#include <cmath>
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

void CheckFinitePosition(std::string_view field, const Position& p) {
  if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) return;
  InvalidParam(field, "a position must be finite, got (" + FormatNumber(p.x) + ", " + FormatNumber(p.y) + ", " +
                          FormatNumber(p.z) + ")");
}

std::string FormatNumber(double v) {
  char buf[64];
  const bool whole = std::isfinite(v) && v == std::trunc(v) && std::fabs(v) < 1e15;
  const auto [end, ec] = whole ? std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, 0)
                               : std::to_chars(buf, buf + sizeof buf, v);
  return ec == std::errc() ? std::string(buf, end) : std::string("?");
}

std::string RangeProblem(std::string_view min, std::string_view max, std::string_view got) {
  return "must be in [" + std::string(min) + ", " + std::string(max) + "], got " + std::string(got);
}

void CheckInRange(std::string_view field, SimTime t, SimTime min, SimTime max) {
  if (t < min || t > max) InvalidParam(field, RangeProblem(FormatDuration(min), FormatDuration(max), FormatDuration(t)));
}

void CheckInRange(std::string_view field, DataRate r, DataRate min, DataRate max) {
  if (r < min || r > max) InvalidParam(field, RangeProblem(ToString(min), ToString(max), ToString(r)));
}

void CheckInRange(std::string_view field, Bytes b, Bytes min, Bytes max) {
  if (b < min || b > max) InvalidParam(field, RangeProblem(ToString(min), ToString(max), ToString(b)));
}

void CheckInRange(std::string_view field, std::int64_t n, std::int64_t min, std::int64_t max) {
  if (n < min || n > max) {
    InvalidParam(field, RangeProblem(std::to_string(min), std::to_string(max), std::to_string(n)));
  }
}

}  // namespace dvpr
