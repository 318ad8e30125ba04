#pragma once
// Channel names. One LCM type per channel; unicast channels carry the
// destination robot's id, broadcast queries share one channel.
#include <string>

#include "agents/ids.h"

namespace dvpr::channels {

inline std::string Query(RobotId dst) { return "DVPR_QUERY_" + std::to_string(dst.value); }
inline const std::string kQueryAll = "DVPR_QUERY_ALL";
inline std::string Match(RobotId dst) { return "DVPR_MATCH_" + std::to_string(dst.value); }
inline std::string VerifyRequest(RobotId dst) { return "DVPR_VREQ_" + std::to_string(dst.value); }
inline std::string VerifyResult(RobotId dst) { return "DVPR_VRES_" + std::to_string(dst.value); }

}  // namespace dvpr::channels
