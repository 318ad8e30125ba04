#pragma once
// The checks that the net_models parameter structs' Validate() share. Each throws
// std::invalid_argument "<field>: <problem>, got <value>", naming the field as the struct spells
// it. A struct that holds another prefixes the inner field ("loss.p"); the config reader prefixes
// the key path of its section ("network."), so the same message serves both.
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>

#include "net_models/units.h"
#include "sim/sim_time.h"

namespace dvpr {

[[noreturn]] void InvalidParam(std::string_view field, const std::string& problem);

// 0 <= p <= 1 (NaN fails).
void CheckProbability(std::string_view field, double p);
void CheckPositiveRate(std::string_view field, DataRate rate);
void CheckNonNegativeDuration(std::string_view field, SimTime t);
void CheckNonNegativeCount(std::string_view field, std::int64_t n);

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
