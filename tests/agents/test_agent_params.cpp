// The agent's parameter structs: Validate() names the offending field as the struct spells it,
// nested fields with their member, so the config reader only prefixes its key path.
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "agents/agent_params.h"

namespace dvpr {
namespace {

std::string ErrorOf(const AgentParams& p) {
  try {
    p.Validate();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(AgentParams, DefaultsAreValid) {
  EXPECT_EQ(ErrorOf(AgentParams{}), "(no error)");
}

TEST(AgentParams, ValidateNamesTheNestedField) {
  AgentParams p;
  p.suppression_frames = -1;
  EXPECT_EQ(ErrorOf(p), "suppression_frames: must not be negative, got -1");
  p = {};
  p.service.per_comparison = SimTime::Nanos(-3);
  EXPECT_EQ(ErrorOf(p), "service.per_comparison: must not be negative, got -3ns");
  p = {};
  p.verification.max_distance = -0.5;
  EXPECT_EQ(ErrorOf(p).rfind("verification.max_distance: must not be negative", 0), 0u) << ErrorOf(p);
  p = {};
  p.verification.request_bytes = Bytes(-1);
  EXPECT_EQ(ErrorOf(p), "verification.request_bytes: must not be negative, got -1");
}

}  // namespace
}  // namespace dvpr
