#pragma once
// The log one `dvpr agent` process leaves for `dvpr launch` to gather: a small
// text file, one record per line, comma-separated, '#' lines are comments.
// Written atomically, so a file that exists is complete; a robot whose process
// died leaves none.
//
//   agent,robot,robots,run,strategy,speedup,start_utime,end_ns,end_reason,
//         published,published_bytes,publish_failures,received,malformed,foreign,medium_wire_bytes,
//         datagrams,malformed_datagrams,duplicates,incomplete_messages,kernel_dropped,out_of_range,
//         unauthenticated,held_dropped,held_bytes_peak
//   load,searches,remote_queries,comparisons,stored,verifications,busy_ns,max_queue
//   sent,dst,messages,payload_bytes,wire_bytes        one line per destination robot
//   recv,src,messages                                 one line per source robot
//   query,frame,sent_ns,expected,received,match_robot,match_frame,distance,latency_ns,
//         verify_requested,verify_accepted            one line per frame taken
//   lost,robot,detected_ns                            one line per robot declared lost (failover)
//
// Times: start_utime is the team's agreed start (wall clock, us since the Unix
// epoch); end_ns and sent_ns are agent time (frame k is taken at k/fps);
// busy_ns is modelled service time (agent time); latency_ns is measured on the
// wall clock (agent-time latency / speedup), empty when a reply is missing.
// end_reason: all_done (every robot announced done) or deadline. Distances are
// written in the shortest form that reads back to the same float.
//
// What the network brought (LcmTransport, agents/udpm/): datagrams read from the group, of
// which malformed (not LCM, cut, fragments that do not fit their message: dropped) and
// duplicates (a fragment already held, or an authenticated sender's message already taken:
// dropped); partial messages
// dropped unfinished; datagrams the kernel dropped because the receive buffer was full. Of the
// messages on the agent's channels, malformed did not decode and foreign came from outside the
// team (another team's heartbeats, robots or frames out of range, a sender that is not the
// robot it names): both dropped.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "agents/algorithms/query_record.h"
#include "agents/robot_agent.h"

namespace dvpr {

struct AgentLinkCount {
  std::int64_t messages = 0;
  std::int64_t payload_bytes = 0;
  std::int64_t wire_bytes = 0;  // the wire-format model of docs/design.md section 4
};

struct AgentLog {
  int robot = 0;
  int robots = 0;
  int run = 0;
  std::string strategy;
  double speedup = 1.0;
  std::int64_t start_utime = 0;
  std::int64_t end_ns = 0;
  std::string end_reason;
  std::uint64_t published = 0;
  std::uint64_t published_bytes = 0;
  std::uint64_t publish_failures = 0;
  std::uint64_t received = 0;    // datagrams on subscribed channels (own broadcast echoes included)
  std::uint64_t malformed = 0;   // buffers that did not decode as the channel's type
  std::uint64_t foreign = 0;     // well-formed messages of another team (heartbeats, ids out of range): dropped
  std::int64_t medium_wire_bytes = 0;  // wire bytes of each publication once
  std::uint64_t datagrams = 0;            // read from the group
  std::uint64_t malformed_datagrams = 0;  // of which not well-formed LCM: dropped
  std::uint64_t duplicates = 0;           // of which repeats (same sender and sequence number): dropped
  std::uint64_t incomplete_messages = 0;  // fragmented messages dropped before their last fragment
  std::uint64_t kernel_dropped = 0;       // lost to a full receive buffer (SO_RXQ_OVFL)
  std::uint64_t out_of_range = 0;         // a radio config: teammates' messages (heartbeats too) from
                                          // robots out of range at agent time (emulated_range.h): dropped
  std::uint64_t unauthenticated = 0;      // messages on its channels whose tag did not verify (not sent
                                          // with the team's secret, or changed): dropped unread
  std::uint64_t held_dropped = 0;         // teammates' messages past --hold-bytes while it waited: dropped
  std::uint64_t held_bytes_peak = 0;      // the most bytes it held at once while it waited
  RobotLoad load;
  std::vector<AgentLinkCount> sent;            // per destination robot
  std::vector<std::int64_t> received_from;     // per source robot (own echoes excluded)
  std::vector<QueryRecord> queries;            // the frames taken; latency: wall clock
  std::vector<LostRobot> lost;                 // failover: robots declared lost, agent time of detection
};

void WriteAgentLog(const std::filesystem::path& path, const AgentLog& log);
// Throws std::runtime_error naming the file and line on anything malformed.
AgentLog ReadAgentLog(const std::filesystem::path& path);

}  // namespace dvpr
