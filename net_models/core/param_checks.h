#pragma once
// The checks that the net_models parameter structs' Validate() share. Each throws
// std::invalid_argument "<field>: <problem>, got <value>", naming the field as the struct spells
// it. A struct that holds another prefixes the inner field ("loss.p"); the config reader prefixes
// the key path of its section ("network."), so the same message serves both.
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>

#include "net_models/core/position.h"
#include "net_models/core/units.h"
#include "sim/sim_time.h"

namespace dvpr {

[[noreturn]] void InvalidParam(std::string_view field, const std::string& problem);

// 0 <= p <= 1 (NaN fails).
void CheckProbability(std::string_view field, double p);
void CheckPositiveRate(std::string_view field, DataRate rate);
void CheckNonNegativeDuration(std::string_view field, SimTime t);
void CheckNonNegativeCount(std::string_view field, std::int64_t n);
// Every coordinate finite (a NaN or an infinity would make every distance meaningless).
void CheckFinitePosition(std::string_view field, const Position& p);

// A number as the range errors write it: whole numbers below 1e15 in full ("1000000"), others in
// the shortest form that reads back to the same double ("0.1", "3.4028234663852886e+38").
std::string FormatNumber(double v);
// The one wording of a range error, "must be in [<min>, <max>], got <got>", for the checks below
// and for a config reader that has the value only as the text the user wrote.
std::string RangeProblem(std::string_view min, std::string_view max, std::string_view got);
// min <= value <= max, else InvalidParam(field, RangeProblem(...)) with each value in its unit's
// canonical form ("24h", "1kbps", "1GiB").
void CheckInRange(std::string_view field, SimTime t, SimTime min, SimTime max);
void CheckInRange(std::string_view field, DataRate r, DataRate min, DataRate max);
void CheckInRange(std::string_view field, Bytes b, Bytes min, Bytes max);
void CheckInRange(std::string_view field, std::int64_t n, std::int64_t min, std::int64_t max);

// Runs validate(); the field named by an error it throws gets `prefix` in front.
template <typename Fn>
void ValidateNested(std::string_view prefix, Fn&& validate) {
  try {
    validate();
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string(prefix) + e.what());
  }
}

}  // namespace dvpr
