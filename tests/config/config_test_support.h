#pragma once
// What the config tests share: a config read from YAML text as "test.yaml" (relative files from
// the source tree), and the error such a text gives.
#include <gtest/gtest.h>

#include <string>

#include "experiments/config/config.h"

namespace dvpr::testing_support {

inline ExperimentConfig ParseTestConfig(const std::string& yaml) {
  return ParseConfig(yaml, DVPR_SOURCE_DIR, {}, "test.yaml");
}

// The ConfigError's message, or "(no error)".
inline std::string ConfigErrorOf(const std::string& yaml) {
  try {
    ParseTestConfig(yaml);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "(no error)";
}

// Expects `error` to begin with `prefix`.
inline void starts_with(const std::string& error, const std::string& prefix) {
  EXPECT_EQ(error.rfind(prefix, 0), 0u) << error;
}

// The short names the config tests use.
inline ExperimentConfig Parse(const std::string& yaml) { return ParseTestConfig(yaml); }
inline std::string ErrorOf(const std::string& yaml) { return ConfigErrorOf(yaml); }

}  // namespace dvpr::testing_support
