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

// Each range's boundary, one inside and one outside (24 h = 86'400'000'000'000 ns; 1 GiB =
// 1'073'741'824 bytes, which the int32 payload_size of verify_request_t holds).
TEST(AgentParams, RangesAcceptTheirBoundsAndRefuseOnePast) {
  AgentParams p;
  p.service.fixed = SimTime::Nanos(86'400'000'000'000);
  p.service.per_comparison = SimTime::Millis(1);
  p.verification.request_bytes = Bytes(1'073'741'824);
  EXPECT_EQ(ErrorOf(p), "(no error)");
  p.service.fixed = SimTime::Nanos(86'400'000'000'001);
  EXPECT_EQ(ErrorOf(p), "service.fixed: must be in [0ns, 24h], got 86400000000001ns");
  p = {};
  p.service.per_comparison = SimTime::Nanos(1'000'001);
  EXPECT_EQ(ErrorOf(p), "service.per_comparison: must be in [0ns, 1ms], got 1000001ns");
  p = {};
  p.verification.request_bytes = Bytes(1'073'741'825);
  EXPECT_EQ(ErrorOf(p), "verification.request_bytes: must be in [0B, 1GiB], got 1073741825B");
  p.verification.request_bytes = Bytes(4'294'992'296);  // the case: as int, 25000
  EXPECT_EQ(ErrorOf(p), "verification.request_bytes: must be in [0B, 1GiB], got 4294992296B");
  p = {};
  p.verification.max_distance = 1e39;  // beyond the largest float
  EXPECT_EQ(ErrorOf(p), "verification.max_distance: must be in [0, 3.4028234663852886e+38], got 1e+39");
}

}  // namespace
}  // namespace dvpr
