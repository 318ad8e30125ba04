#pragma once
// queries.csv's `hops` (written when a network variant of the sweep is a radio): how far the
// answer to each query came, read from the network's hooks without the agents knowing.
//
// A query's hops are those of the copy of the query that reached the robot whose reply gave the
// query's best match: 1 straight to it, more through relays, 0 when the querying robot's own
// store gave the best match (no copy travelled), none when no match came back. The replying
// robot is the one whose delivered reply (match_t or bow_match_t) names the best match's robot
// and frame; when several name it (replicas of one frame), the reply delivered first, as the
// agents keep the earlier of equal matches.
#include <cstdint>
#include <optional>
#include <unordered_map>
#include <vector>

#include "agents/algorithms/query_record.h"
#include "agents/messages/lcm_codec.h"
#include "net_models/network/network_observer.h"

namespace dvpr {

class QueryHopsRecorder : public NetworkObserver {
 public:
  void OnDelivered(const MessageCopy& copy, SimTime at) override;

  // The hops of `q` as above; call after the run.
  std::optional<int> HopsOf(const QueryRecord& q) const;

 private:
  struct Reply {
    int responder = 0;
    int match_robot = 0;
    std::int32_t match_frame = 0;
  };
  void OnRequest(int robot, std::int32_t frame, const MessageCopy& copy);
  template <typename Match>  // match_t or bow_match_t
  void OnReply(const Match& m);

  // (querying robot, frame, receiving robot) -> hops of the first copy of the query delivered there.
  std::unordered_map<std::uint64_t, int> request_hops_;
  // (querying robot, frame) -> the replies with a match, in delivery order.
  std::unordered_map<std::uint64_t, std::vector<Reply>> replies_;
  // Decoded into again and again, so a warm run allocates nothing per copy.
  query_t query_;
  bow_query_t bow_query_;
  match_t match_;
  bow_match_t bow_match_;
};

}  // namespace dvpr
