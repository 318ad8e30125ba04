#pragma once
// The rows of the result files (docs/design.md section 6). The static protocol and the simulation
// fill them; experiments/results/result_writers.h turns them into CSV/JSON. Plain data, no
// behaviour, so every producer can fill them without knowing how they are written.
//
// Conventions:
// - Identification fields (protocol, strategy, robots, run, seed, network_*) are stamped by the run
//   executor from the RunSpec; a run function may leave them default.
// - A double that does not apply (e.g. latency in the static protocol) stays NaN and is written as
//   an empty CSV field; an optional that is empty is written as an empty field.
#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "lcmtypes/channels/message_role.h"

namespace dvpr {

inline constexpr double kNotApplicable = std::numeric_limits<double>::quiet_NaN();

// Which network a row was produced on. Empty model for the paper protocol (no network).
struct NetworkLabel {
  int variant = 0;            // index into the sweep's network variants (0 when no sweep)
  std::string model;          // ideal | point_to_point | shared_medium; "" for protocol=paper
  double bandwidth_bps = kNotApplicable;
  double latency_ms = kNotApplicable;
  std::string loss;           // none | bernoulli | gilbert_elliott
  int queue_packets = 0;      // named only where the sweep lists several queues or MTUs; 0 otherwise
  int mtu_bytes = 0;
  // The propagation of a medium that has one (a radio; wifi over a radio's range), as names show
  // it ("range 200m" | "log_distance"), and the range as a number (NaN unless a range
  // propagation). Both "" / NaN on the full mesh. Made once, where the variants are expanded
  // (experiments/config/network_variants.h); read as fields, never parsed back from the name.
  std::string propagation = {};
  double range_m = kNotApplicable;
  std::string next_hop = {};  // "shortest_path" | "link_state"; "" for direct (the default)
};

// How a network variant is named. kColumn: "point-to-point 10 Mbit/s 2 ms" (+ " bernoulli loss",
// + " range 200m shortest_path" on a radio), the summary table's, the CSVs' network_name column's,
// the progress lines' and the figures' legends'; no commas, so a CSV field needs no quoting.
// kPage: the same parts separated by ", " ("point-to-point, 10 Mbit/s, 2 ms, loss: bernoulli"),
// the replay page's heading. "" without a network.
enum class NameStyle { kColumn, kPage };
std::string NetworkName(const NetworkLabel& network, NameStyle style = NameStyle::kColumn);

// The byte columns by message role (MessageRole, lcmtypes/channels/message_role.h) of runs.csv
// and links.csv follow the role order; every message has exactly one role, so the roles' bytes
// sum to each total.
inline constexpr std::array<const char*, kMessageRoles> kMessageRoleNames = {
    "query", "reply", "verify_request", "verify_result", "recluster", "other"};

// Bytes of the copies of messages (one copy per destination): offered (sent, whatever became of
// them) and delivered. wire = the copy's LCM/UDP/IP/link bytes (wire_format.h).
struct CopyBytes {
  std::int64_t payload = 0;
  std::int64_t wire = 0;
  std::int64_t delivered_payload = 0;
  std::int64_t delivered_wire = 0;
  CopyBytes& operator+=(const CopyBytes& o) {
    payload += o.payload;
    wire += o.wire;
    delivered_payload += o.delivered_payload;
    delivered_wire += o.delivered_wire;
    return *this;
  }
};
using RoleCopyBytes = std::array<CopyBytes, kMessageRoles>;

// A run's bytes by role, counted by the simulated network (absent for rows without one).
struct RunRoleBytes {
  RoleCopyBytes copies{};                               // per role, summed over all pairs
  std::array<std::int64_t, kMessageRoles> medium{};     // per role: bytes put on the medium
};

// Common key of every row: which run of the sweep produced it.
struct RunKey {
  std::string protocol;       // paper | sim
  std::string strategy;       // decentralized | broadcast | ...
  int robots = 0;
  int run = 0;                // numbered from 0
  NetworkLabel network;
};

// One row of runs.csv.
// A team run's place recognition by class and its inter-robot loop closures (docs/design.md
// section 3, "Inter-robot loop closures"; experiments/domain/evaluation/sim_metrics.h): the trailing
// columns of runs.csv.
struct RunClosures {
  std::int64_t inter_queries = 0;     // relevant queries whose true match is another robot's frame
  std::int64_t intra_queries = 0;     // relevant queries whose true matches are all the robot's own
  std::int64_t inter_recognised = 0;  // of which the returned match was correct
  std::int64_t intra_recognised = 0;
  double inter_auc = kNotApplicable;  // PR AUC over the class's queries; not applicable when none
  double intra_auc = kNotApplicable;
  std::int64_t inter_candidates = 0;  // verifications asked for with another robot's frame
  std::int64_t inter_closures = 0;    // of which accepted: inter-robot loop closures found
  std::int64_t pairs_closed = 0;      // pairs of robots that found one
  std::optional<std::int64_t> median_first_closure_ns;  // over those pairs: when their first was sent

  // Each not applicable over none. Closure precision: every accepted verification is a true
  // match (the verifier checks the ground truth), so it is the candidates' share of true ones.
  double inter_recall() const { return Ratio(inter_recognised, inter_queries); }
  double intra_recall() const { return Ratio(intra_recognised, intra_queries); }
  double closure_precision() const { return Ratio(inter_closures, inter_candidates); }
  double median_first_closure_s() const {
    return median_first_closure_ns ? static_cast<double>(*median_first_closure_ns) / 1e9 : kNotApplicable;
  }

 private:
  static double Ratio(std::int64_t a, std::int64_t b) {
    return b > 0 ? static_cast<double>(a) / static_cast<double>(b) : kNotApplicable;
  }
};

struct RunResult {
  RunKey key;
  std::uint64_t seed = 0;
  double auc = kNotApplicable;
  double auc_reference = kNotApplicable;  // centralized (paper) or broadcast of the same run (sim)
  double relative_auc = kNotApplicable;   // auc / auc_reference
  double worst_balance_ratio = kNotApplicable;
  std::int64_t queries = 0;
  std::int64_t messages = 0;
  std::int64_t payload_bytes = 0;
  std::int64_t wire_bytes = 0;
  double bytes_per_query = kNotApplicable;  // wire bytes per query
  double mean_latency_ms = kNotApplicable;
  double p99_latency_ms = kNotApplicable;
  std::int64_t dropped_messages = 0;
  std::optional<RunRoleBytes> roles;        // sim only: the network's bytes by message role
  double duration_s = kNotApplicable;       // sim only: how long the robots drove (offered load = bytes / this)
  std::optional<RunClosures> closures;      // sim and lcm only: inter- and intra-robot recognition
};

// One row of per_robot.csv.
struct RobotLoadRow {
  RunKey key;
  int robot = 0;
  std::int64_t queries_received = 0;
  std::int64_t comparisons = 0;
  std::int64_t stored = 0;
  double busy_fraction = kNotApplicable;  // sim only
  std::int64_t max_queue = 0;
  // Sim only: its transmissions of others' messages and their frame bytes (multi-hop routing);
  // per_robot.csv has these columns only when a network variant is a radio.
  std::int64_t relay_transmissions = 0;
  std::int64_t relay_bytes = 0;
  // Sim only, the same columns: its routing beacons' transmissions and frame bytes (link_state).
  std::int64_t routing_transmissions = 0;
  std::int64_t routing_bytes = 0;
  // Sim on a contending medium (csma, wifi) only: what its medium access did (mac_counters.h);
  // per_robot.csv has these columns only when a network variant contends. airtime_share: its
  // attempts' medium time over the run's simulated time.
  std::int64_t mac_attempts = 0;
  std::int64_t mac_backoffs = 0;
  std::int64_t mac_collisions = 0;
  std::int64_t mac_retries = 0;
  std::int64_t mac_dropped_queue_full = 0;
  std::int64_t mac_dropped_retry_limit = 0;
  double airtime_share = kNotApplicable;
};

// One row of failover.csv (written when the config has a dropout): one dropped robot of a run
// (docs/failover.md).
struct FailoverRow {
  RunKey key;
  int robot = 0;                          // the dropped robot
  std::int64_t at_ns = 0;                 // when it dropped
  std::optional<std::int64_t> detected_ns;  // when the last robot that stayed declared it lost
  std::int64_t stored = 0;                // descriptors it held: gone with it
  std::int64_t kept = 0;                  // of which a copy survives at a robot that stayed
  std::int64_t incomplete_queries = 0;    // the run's queries with a reply that never came
};

// One row of links.csv: one directed pair (src -> dst) of one run.
struct LinkRow {
  RunKey key;
  int src = 0;
  int dst = 0;
  std::int64_t messages = 0;
  std::int64_t payload_bytes = 0;
  std::int64_t wire_bytes = 0;
  std::int64_t dropped = 0;
  std::optional<RoleCopyBytes> roles;  // sim only: this pair's bytes by message role
};

// One row of queries.csv (written when outputs.queries is true).
struct QueryRow {
  RunKey key;
  int robot = 0;
  std::int64_t frame = 0;              // index in the full sequence
  std::int64_t sent_ns = 0;
  std::optional<int> match_robot;      // empty when no match came back
  std::optional<std::int64_t> match_frame;
  double distance = kNotApplicable;    // squared L2 of the best match; NaN when none
  std::optional<std::int64_t> latency_ns;
  bool relevant = false;
  bool correct = false;
  // "inter" when one of the query's true matches is another robot's frame, "intra" when they
  // are all its own, "" when it is not relevant (experiments/domain/evaluation/sim_metrics.h).
  std::string query_class;
  // How far the answer came (experiments/protocols/sim/query_hops.h): the transmissions of the
  // query's copy that reached the robot whose reply gave the best match, 0 when the robot's own
  // store gave it, empty when no match came back. A column of queries.csv only when a network
  // variant is a radio.
  std::optional<int> hops;
};

// One row of messages.csv (written when outputs.messages is true): one message and destination.
struct MessageRow {
  RunKey key;
  std::int64_t sent_ns = 0;
  std::optional<std::int64_t> delivered_ns;  // empty when dropped
  int src = 0;
  int dst = 0;
  std::string channel;
  std::string type;                    // LCM type name, e.g. dvpr.query_t
  std::int64_t payload_bytes = 0;
  std::int64_t wire_bytes = 0;
  bool dropped = false;
  std::string role;                    // kMessageRoleNames; "" when the producer knows none
  // Transmissions the copy completed (MessageCopy::hops): 1 straight to its destination; a
  // column of messages.csv only when a network variant is a radio.
  int hops = 0;
};

// A precision-recall curve in ranking order (for figure 2). label says what it is, e.g.
// "centralized" or "decentralized".
struct PrCurve {
  std::string label;
  int robots = 0;
  int run = 0;
  std::vector<double> recall;
  std::vector<double> precision;
};

}  // namespace dvpr
