#pragma once
// What the config tests share: a config read from YAML text as "test.yaml" (relative files from
// the source tree), and the error such a text gives.
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

}  // namespace dvpr::testing_support
