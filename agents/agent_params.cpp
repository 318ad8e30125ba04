#include "agents/agent_params.h"

#include <sstream>
#include <stdexcept>
#include <string>

#include "net_models/core/param_checks.h"

namespace dvpr {

void ServiceParams::Validate() const {
  CheckNonNegativeDuration("fixed", fixed);
  CheckInRange("fixed", fixed, SimTime::Zero(), kMaxFixed);
  CheckNonNegativeDuration("per_comparison", per_comparison);
  CheckInRange("per_comparison", per_comparison, SimTime::Zero(), kMaxPerComparison);
}

void VerificationParams::Validate() const {
  CheckNonNegativeCount("request_bytes", request_bytes.value());
  CheckInRange("request_bytes", request_bytes, Bytes(0), kMaxRequestBytes);
  if (!(max_distance >= 0.0)) {
    std::ostringstream got;
    got << max_distance;
    InvalidParam("max_distance", "must not be negative, got " + got.str());
  }
  if (!(max_distance <= kMaxDistance)) {
    InvalidParam("max_distance", RangeProblem("0", FormatNumber(kMaxDistance), FormatNumber(max_distance)));
  }
  if (!(bow_max_distance >= 0.0 && bow_max_distance <= 1.0)) {
    InvalidParam("bow_max_distance", RangeProblem("0", "1", FormatNumber(bow_max_distance)));
  }
}

void AgentParams::Validate() const {
  CheckNonNegativeCount("suppression_frames", suppression_frames);
  ValidateNested("service.", [&] { service.Validate(); });
  ValidateNested("verification.", [&] { verification.Validate(); });
}

}  // namespace dvpr
