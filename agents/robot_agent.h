#pragma once
// One robot of the team: takes a frame every 1/fps, routes its descriptor as a
// query, serves the queries routed to it one at a time (search, store, reply),
// and follows a good match with a geometric-verification exchange with the
// robot that observed the matched frame (DESIGN.md sections 1 and 3).
//
// The agent only records what happened (QueryOutcome, RobotLoad); metrics are
// computed elsewhere from those records. It talks only through Transport, so
// the same code runs in virtual time and as a real LCM process.
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "agents/agent_params.h"
#include "agents/descriptor_index.h"
#include "agents/descriptors.h"
#include "agents/ids.h"
#include "agents/routing.h"
#include "agents/transport.h"
#include "sim/sim_time.h"

namespace dvpr {

// The frames a robot takes: rows [first, first + count) of the full sequence.
struct FrameStream {
  const DescriptorMatrix* descriptors = nullptr;
  FrameId first{0};
  int count = 0;
  double fps = 10.0;
  SimTime TimeOf(int k) const;  // k-th frame at k / fps
};

// What the querying robot learned about one of its frames.
struct QueryOutcome {
  FrameId frame;
  SimTime sent;
  int expected_replies = 0;                // searches asked for (local one included)
  int received_replies = 0;
  std::optional<IndexMatch> best;          // best over the replies received
  std::optional<SimTime> last_reply;       // arrival of the last reply received
  bool verify_requested = false;
  std::optional<bool> verify_accepted;
  std::optional<SimTime> verify_done;
  bool Complete() const { return received_replies == expected_replies; }
};

// Load a robot carried while serving (DESIGN.md section 3, per-robot load).
struct RobotLoad {
  std::int64_t searches = 0;               // queries served: remote and its own local ones
  std::int64_t remote_queries = 0;         // of which arrived over the network
  std::int64_t comparisons = 0;
  std::int64_t stored = 0;
  std::int64_t verifications = 0;
  SimTime busy;                            // total service time
  std::int64_t max_queue = 0;              // longest wait line seen (the task in service excluded)
};

struct VerifyVerdict {
  bool accepted = false;
  int inliers = 0;
};
// Geometric verification as the robot that saw `match` runs it against the
// query's keypoints. The simulation supplies one that checks the poses.
using GeometricVerifier = std::function<VerifyVerdict(FrameId query, FrameId match)>;

class CentroidTable;
class centroid_table_t;
class descriptor_batch_t;
struct ReclusterState;

class RobotAgent {
 public:
  RobotAgent(RobotId id, const AgentParams& params, Transport& transport, const RoutingStrategy& routing,
             FrameStream frames, GeometricVerifier verifier);
  RobotAgent(const RobotAgent&) = delete;
  RobotAgent& operator=(const RobotAgent&) = delete;
  ~RobotAgent();

  // Subscribes to the robot's channels and schedules its first frame at t = 0.
  void Start();
  // From now on the robot takes no frames and serves nothing (dropout).
  void GoOffline();

  RobotId id() const { return id_; }
  const std::vector<QueryOutcome>& outcomes() const { return outcomes_; }
  const RobotLoad& load() const { return load_; }
  const IncrementalIndex& index() const { return index_; }
  // Adaptive re-clustering (agents/recluster_agent.h), when the routing is a ReclusterRouting:
  // this robot's current epoch and table. 0 and nullptr for every other routing.
  int recluster_epoch() const;
  const CentroidTable* recluster_table() const;

 private:
  struct Task {
    enum class Kind { kSearch, kVerify } kind = Kind::kSearch;
    RobotId querier;
    FrameId frame;
    std::vector<float> descriptor;  // kSearch
    bool store = false;             // kSearch: keep the descriptor after searching
    FrameId match_frame;            // kVerify
    RobotId match_robot;
  };

  void TakeFrame(int k);
  void PublishQuery(int k, const RoutingDecision& decision);
  void Enqueue(Task task);
  void StartNextTask();
  void ServeSearch(Task task);
  void ServeVerify(Task task);
  void OnQuery(const query_t& q);
  void OnMatch(const match_t& m);
  void OnVerifyRequest(const verify_request_t& r);
  void OnVerifyResult(const verify_result_t& r);
  void RecordReply(FrameId frame, const std::optional<IndexMatch>& match);
  void MaybeVerify(int k);
  int LocalIndexOf(FrameId frame) const;
  bool Contains(const std::vector<RobotId>& robots, RobotId r) const;
  void StoreQuery(RobotId robot, FrameId frame, const float* descriptor);

  // Re-clustering (robot_agent_recluster.cpp); recluster_ stays null for other routings, whose
  // code paths do not change.
  void InitRecluster();
  void StartRecluster();
  RoutingDecision ReclusterRoute(const float* descriptor) const;
  void StoreOrForward(RobotId robot, FrameId frame, const float* descriptor);
  void OnEpochBoundary(int epoch);
  void OnSample(const descriptor_batch_t& b);
  void LeaderCompute(int epoch, bool timed_out);
  void OnTable(const centroid_table_t& t);
  void AdoptTable(std::shared_ptr<const CentroidTable> table, int epoch);
  void OnMigration(const descriptor_batch_t& b);

  RobotId id_;
  AgentParams params_;
  Transport& transport_;
  const RoutingStrategy& routing_;
  FrameStream frames_;
  GeometricVerifier verifier_;
  IncrementalIndex index_;
  std::vector<QueryOutcome> outcomes_;
  RobotLoad load_;
  std::deque<Task> queue_;
  bool busy_ = false;
  bool online_ = true;
  std::vector<Subscription> subscriptions_;
  std::unique_ptr<ReclusterState> recluster_;
};

}  // namespace dvpr
