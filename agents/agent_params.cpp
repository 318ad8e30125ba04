#include "agents/agent_params.h"

#include <sstream>
#include <stdexcept>
#include <string>

#include "net_models/param_checks.h"

namespace dvpr {

void ServiceParams::Validate() const {
  CheckNonNegativeDuration("fixed", fixed);
  CheckNonNegativeDuration("per_comparison", per_comparison);
}

void VerificationParams::Validate() const {
  CheckNonNegativeCount("request_bytes", request_bytes.value());
  if (!(max_distance >= 0.0)) {
    std::ostringstream got;
    got << max_distance;
    InvalidParam("max_distance", "must not be negative, got " + got.str());
  }
}

void AgentParams::Validate() const {
  CheckNonNegativeCount("suppression_frames", suppression_frames);
  ValidateNested("service.", [&] { service.Validate(); });
  ValidateNested("verification.", [&] { verification.Validate(); });
}

}  // namespace dvpr
