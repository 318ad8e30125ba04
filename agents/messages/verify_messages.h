#pragma once
// The two messages of the geometric-verification exchange (docs/design.md section 3) as every team
// agent fills them: RobotAgent and BowRobotAgent differ in what they verify and how they send
// it, not in these fields.
#include <cstdint>
#include <dvpr/verify_request_t.hpp>
#include <dvpr/verify_result_t.hpp>

#include "agents/algorithms/geometric_verifier.h"
#include "agents/algorithms/ids.h"

namespace dvpr {

// `r` asks `match_robot` to verify `querier`'s frame against `match_frame`: every field set and
// the payload resized to `payload_bytes`, its bytes left for the caller to write
// (FillVerificationPayload). `r` may be a request reused from an earlier one.
void FillVerifyRequest(verify_request_t& r, std::int64_t utime, RobotId querier, FrameId frame, RobotId match_robot,
                       FrameId match_frame, std::int32_t payload_bytes);

// `observer`'s verdict on `querier`'s frame against its own `match_frame`.
verify_result_t MakeVerifyResult(std::int64_t utime, RobotId querier, FrameId frame, RobotId observer,
                                 FrameId match_frame, const VerifyVerdict& verdict);

}  // namespace dvpr
