#include "agents/messages/verify_messages.h"

#include <cstddef>

namespace dvpr {

void FillVerifyRequest(verify_request_t& r, std::int64_t utime, RobotId querier, FrameId frame, RobotId match_robot,
                       FrameId match_frame, std::int32_t payload_bytes) {
  r.utime = utime;
  r.query_robot = static_cast<std::int16_t>(querier.value);
  r.query_frame = frame.value;
  r.match_robot = static_cast<std::int16_t>(match_robot.value);
  r.match_frame = match_frame.value;
  r.payload_size = payload_bytes;
  r.payload.resize(static_cast<std::size_t>(payload_bytes));
}

verify_result_t MakeVerifyResult(std::int64_t utime, RobotId querier, FrameId frame, RobotId observer,
                                 FrameId match_frame, const VerifyVerdict& verdict) {
  verify_result_t v;
  v.utime = utime;
  v.query_robot = static_cast<std::int16_t>(querier.value);
  v.query_frame = frame.value;
  v.match_robot = static_cast<std::int16_t>(observer.value);
  v.match_frame = match_frame.value;
  v.accepted = verdict.accepted;
  v.inliers = verdict.inliers;
  return v;
}

}  // namespace dvpr
