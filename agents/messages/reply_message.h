#pragma once
// A responder's reply to a query (match_t for descriptors, bow_match_t for bag-of-words parts):
// the fields both messages share, filled in one place. What the match is worth (a squared
// distance, a partial score) is the caller's to set.
#include <cstdint>
#include <optional>

#include "agents/algorithms/ids.h"

namespace dvpr {

// `responder`'s answer to `querier`'s frame: `best`, or none (match_robot and match_frame -1).
// `Match` has robot and frame.
template <class Reply, class Match>
Reply MakeReply(std::int64_t utime, RobotId querier, FrameId frame, RobotId responder, const std::optional<Match>& best) {
  Reply m;
  m.utime = utime;
  m.query_robot = static_cast<std::int16_t>(querier.value);
  m.query_frame = frame.value;
  m.responder = static_cast<std::int16_t>(responder.value);
  m.has_match = best.has_value();
  m.match_robot = best ? static_cast<std::int16_t>(best->robot.value) : std::int16_t{-1};
  m.match_frame = best ? best->frame.value : -1;
  return m;
}

}  // namespace dvpr
