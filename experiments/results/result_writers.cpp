#include "experiments/results/result_writers.h"

#include <unistd.h>

#include <charconv>
#include <cmath>
#include <map>
#include <sstream>
#include <stdexcept>
#include <system_error>

namespace dvpr {

// Network columns come after the ones docs/design.md requires, so scripts reading by position still
// find the required columns first; the columns of issue 16 (network name, bytes by role) after
// those, and messages.csv's role last of all.
#define DVPR_NETWORK_COLUMNS "network_variant,network_model,bandwidth_bps,latency_ms,loss,network_name"

namespace {

// ",query_<a>,query_<b>,...,reply_<a>,...": the by-role columns, role-major.
std::string RoleColumns(std::initializer_list<const char*> suffixes) {
  std::string out;
  for (const char* role : kMessageRoleNames) {
    for (const char* suffix : suffixes) out += std::string(",") + role + "_" + suffix;
  }
  return out;
}

const std::string& RunsHeaderText() {
  static const std::string h =
      "protocol,strategy,robots,run,seed,auc,auc_reference,relative_auc,worst_balance_ratio,"
      "queries,messages,payload_bytes,wire_bytes,bytes_per_query,mean_latency_ms,p99_latency_ms,"
      "dropped_messages," DVPR_NETWORK_COLUMNS ",duration_s,copy_wire_bytes,delivered_payload_bytes,delivered_wire_bytes" +
      RoleColumns({"payload_bytes", "wire_bytes", "copy_wire_bytes", "delivered_payload_bytes",
                   "delivered_wire_bytes"}) +
      ",inter_queries,intra_queries,inter_recall,intra_recall,inter_auc,intra_auc,inter_candidates,inter_closures,"
      "closure_precision,pairs_closed,median_first_closure_s";
  return h;
}

const std::string& LinksHeaderText() {
  static const std::string h =
      "protocol,strategy,robots,run,src,dst,messages,payload_bytes,wire_bytes,dropped,"
      DVPR_NETWORK_COLUMNS ",delivered_payload_bytes,delivered_wire_bytes" +
      RoleColumns({"payload_bytes", "wire_bytes", "delivered_payload_bytes", "delivered_wire_bytes"});
  return h;
}

}  // namespace

const char* const kRunsHeader = RunsHeaderText().c_str();
const char* const kPerRobotHeader =
    "protocol,strategy,robots,run,robot,queries_received,comparisons,stored,busy_fraction,"
    "max_queue," DVPR_NETWORK_COLUMNS;
const char* const kLinksHeader = LinksHeaderText().c_str();
const char* const kQueriesHeader =
    "protocol,strategy,robots,run,robot,frame,sent_ns,match_robot,match_frame,distance,"
    "latency_ns,relevant,correct," DVPR_NETWORK_COLUMNS ",class";
const char* const kMessagesHeader =
    "protocol,strategy,robots,run,sent_ns,delivered_ns,src,dst,channel,type,payload_bytes,"
    "wire_bytes,dropped," DVPR_NETWORK_COLUMNS ",role";
const char* const kFailoverHeader =
    "protocol,strategy,robots,run,robot,at_ns,detected_ns,stored,kept,incomplete_queries," DVPR_NETWORK_COLUMNS;
const char* const kBowHeader =
    "protocol,strategy,robots,run,queries,partial_queries,payload_bytes,query_bytes_per_query,mean_words,"
    "mean_part_words,part_bytes_p50,part_bytes_p90,part_bytes_max,voted,vote_not_centralized,"
    "vote_not_centralized_fraction," DVPR_NETWORK_COLUMNS;
const char* const kBowSizesHeader = "protocol,strategy,robots,run,payload_bytes,messages," DVPR_NETWORK_COLUMNS;
const char* const kRadioHeader =
    "protocol,strategy,robots,run,delivered_copies,mean_hops,max_hops,relay_transmissions,relay_bytes,held_copies,"
    "routing_transmissions,routing_bytes,"
    "dropped_queue_full,dropped_loss,dropped_offline,dropped_no_route,dropped_out_of_range,dropped_hop_limit,"
    "dropped_buffer_full,dropped_expired,dropped_stale_route,dropped_retry_limit,dropped_collision," DVPR_NETWORK_COLUMNS
    ",delivered_by_hops";
const char* const kMediumHeader =
    "protocol,strategy,robots,run,delivered_copies,attempts,backoffs,collisions,retries,airtime_ns,busy_ns,"
    "medium_utilisation,dropped_queue_full,dropped_loss,dropped_offline,dropped_no_route,dropped_out_of_range,"
    "dropped_hop_limit,dropped_buffer_full,dropped_expired,dropped_stale_route,dropped_retry_limit,"
    "dropped_collision," DVPR_NETWORK_COLUMNS;
const char* const kClosurePairsHeader =
    "protocol,strategy,robots,run,robot_a,robot_b,first_closure_ns," DVPR_NETWORK_COLUMNS;
#undef DVPR_NETWORK_COLUMNS

namespace {

// A latency in the unit that reads naturally: "1 us" (not "0.001 ms"), "2 ms", "1.5 s"; to the ns.
std::string LatencyText(double ms) {
  const double ns = std::round(ms * 1e6);
  if (ns != 0 && std::fabs(ns) < 1e6) return FormatDouble(ns / 1e3) + " us";
  if (std::fabs(ns) >= 1e9) return FormatDouble(ns / 1e9) + " s";
  return FormatDouble(ms) + " ms";
}

}  // namespace

std::string NetworkName(const NetworkLabel& n, NameStyle style) {
  if (n.model.empty()) return "";
  std::vector<std::string> parts = {n.model == "point_to_point"  ? "point-to-point"
                                    : n.model == "shared_medium" ? "shared medium"
                                                                 : n.model};
  const double bps = n.bandwidth_bps;
  if (!std::isnan(bps)) {
    if (bps >= 1e9 && std::fmod(bps, 1e9) == 0) {
      parts.push_back(FormatDouble(bps / 1e9) + " Gbit/s");
    } else if (bps >= 1e6) {
      parts.push_back(FormatDouble(bps / 1e6) + " Mbit/s");
    } else {
      parts.push_back(FormatDouble(bps / 1e3) + " kbit/s");
    }
  }
  if (!std::isnan(n.latency_ms)) parts.push_back(LatencyText(n.latency_ms));
  if (n.queue_packets > 0) parts.push_back("queue " + std::to_string(n.queue_packets) + " packets");
  if (n.mtu_bytes > 0) parts.push_back("MTU " + std::to_string(n.mtu_bytes) + " B");
  const bool page = style == NameStyle::kPage;
  if (!n.loss.empty() && n.loss != "none") parts.push_back(page ? "loss: " + n.loss : n.loss + " loss");
  // The page keeps a radio's propagation and next hop together ("range 200m link_state").
  const std::string sep = page ? ", " : " ";
  const std::string tail = n.propagation + (!n.propagation.empty() && !n.next_hop.empty() ? " " : "") + n.next_hop;
  if (!tail.empty()) parts.push_back(tail);
  std::string name = parts.front();
  for (std::size_t i = 1; i < parts.size(); ++i) name += sep + parts[i];
  return name;
}

std::string FormatDouble(double v) {
  if (std::isnan(v)) return "";
  if (v == 0.0) v = 0.0;  // no "-0"
  char buf[64];  // the longest shortest form of a double is 24 characters
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  if (ec != std::errc()) return "";
  return std::string(buf, end);
}

std::string FormatDouble(double v, int decimals) {
  if (std::isnan(v)) return "";
  if (v == 0.0) v = 0.0;  // no "-0.000000"
  char buf[64];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, decimals);
  if (ec != std::errc()) return "";
  return std::string(buf, end);
}

namespace {

template <typename T>
std::string Opt(const std::optional<T>& v) { return v ? std::to_string(*v) : std::string(); }

std::string Key(const RunKey& k) {
  return k.protocol + "," + k.strategy + "," + std::to_string(k.robots) + "," +
         std::to_string(k.run);
}

std::string Network(const NetworkLabel& n) {
  if (n.model.empty()) return ",,,,,";  // protocol=paper: no network
  return std::to_string(n.variant) + "," + n.model + "," + FormatDouble(n.bandwidth_bps) +
         "," + FormatDouble(n.latency_ms) + "," + n.loss + "," + NetworkName(n);
}

// Empty fields where a row has no bytes by role (no simulated network counted them).
std::string Empty(int fields) { return std::string(static_cast<std::size_t>(fields), ','); }

std::string RunRoles(const std::optional<RunRoleBytes>& roles) {
  if (!roles) return Empty(3 + 5 * kMessageRoles);
  CopyBytes total;
  for (const CopyBytes& c : roles->copies) total += c;
  std::string out = "," + std::to_string(total.wire) + "," + std::to_string(total.delivered_payload) + "," +
                    std::to_string(total.delivered_wire);
  for (int i = 0; i < kMessageRoles; ++i) {
    const CopyBytes& c = roles->copies[static_cast<std::size_t>(i)];
    out += "," + std::to_string(c.payload) + "," + std::to_string(roles->medium[static_cast<std::size_t>(i)]) +
           "," + std::to_string(c.wire) + "," + std::to_string(c.delivered_payload) + "," +
           std::to_string(c.delivered_wire);
  }
  return out;
}

// runs.csv's last columns (RunClosures).
std::string Closures(const std::optional<RunClosures>& c) {
  if (!c) return Empty(11);
  return "," + std::to_string(c->inter_queries) + "," + std::to_string(c->intra_queries) + "," +
         FormatDouble(c->inter_recall()) + "," + FormatDouble(c->intra_recall()) + "," + FormatDouble(c->inter_auc) +
         "," + FormatDouble(c->intra_auc) + "," + std::to_string(c->inter_candidates) + "," +
         std::to_string(c->inter_closures) + "," + FormatDouble(c->closure_precision()) + "," +
         std::to_string(c->pairs_closed) + "," + FormatDouble(c->median_first_closure_s());
}

std::string LinkRoles(const std::optional<RoleCopyBytes>& roles) {
  if (!roles) return Empty(2 + 4 * kMessageRoles);
  CopyBytes total;
  for (const CopyBytes& c : *roles) total += c;
  std::string out = "," + std::to_string(total.delivered_payload) + "," + std::to_string(total.delivered_wire);
  for (const CopyBytes& c : *roles) {
    out += "," + std::to_string(c.payload) + "," + std::to_string(c.wire) + "," +
           std::to_string(c.delivered_payload) + "," + std::to_string(c.delivered_wire);
  }
  return out;
}

}  // namespace

std::string CsvRow(const RunResult& r) {
  std::ostringstream s;
  s << Key(r.key) << ',' << r.seed << ',' << FormatDouble(r.auc) << ','
    << FormatDouble(r.auc_reference) << ',' << FormatDouble(r.relative_auc) << ','
    << FormatDouble(r.worst_balance_ratio) << ',' << r.queries << ',' << r.messages << ','
    << r.payload_bytes << ',' << r.wire_bytes << ',' << FormatDouble(r.bytes_per_query) << ','
    << FormatDouble(r.mean_latency_ms) << ',' << FormatDouble(r.p99_latency_ms) << ','
    << r.dropped_messages << ',' << Network(r.key.network) << ',' << FormatDouble(r.duration_s)
    << RunRoles(r.roles) << Closures(r.closures);
  return s.str();
}

std::string CsvRow(const RobotLoadRow& r) {
  return Key(r.key) + "," + std::to_string(r.robot) + "," + std::to_string(r.queries_received) +
         "," + std::to_string(r.comparisons) + "," + std::to_string(r.stored) + "," +
         FormatDouble(r.busy_fraction) + "," + std::to_string(r.max_queue) + "," +
         Network(r.key.network);
}

std::string CsvRow(const FailoverRow& r) {
  return Key(r.key) + "," + std::to_string(r.robot) + "," + std::to_string(r.at_ns) + "," +
         (r.detected_ns ? std::to_string(*r.detected_ns) : std::string()) + "," + std::to_string(r.stored) + "," +
         std::to_string(r.kept) + "," + std::to_string(r.incomplete_queries) + "," + Network(r.key.network);
}

std::string CsvRow(const LinkRow& r) {
  return Key(r.key) + "," + std::to_string(r.src) + "," + std::to_string(r.dst) + "," +
         std::to_string(r.messages) + "," + std::to_string(r.payload_bytes) + "," +
         std::to_string(r.wire_bytes) + "," + std::to_string(r.dropped) + "," +
         Network(r.key.network) + LinkRoles(r.roles);
}

std::string CsvRow(const QueryRow& r) {
  return Key(r.key) + "," + std::to_string(r.robot) + "," + std::to_string(r.frame) + "," +
         std::to_string(r.sent_ns) + "," + Opt(r.match_robot) + "," + Opt(r.match_frame) + "," +
         FormatDouble(r.distance) + "," + Opt(r.latency_ns) + "," + (r.relevant ? "1" : "0") +
         "," + (r.correct ? "1" : "0") + "," + Network(r.key.network) + "," + r.query_class;
}

std::string CsvRow(const ClosurePairRow& r) {
  return Key(r.key) + "," + std::to_string(r.robot_a) + "," + std::to_string(r.robot_b) + "," +
         Opt(r.first_closure_ns) + "," + Network(r.key.network);
}

std::string CsvRow(const MessageRow& r) {
  return Key(r.key) + "," + std::to_string(r.sent_ns) + "," + Opt(r.delivered_ns) + "," +
         std::to_string(r.src) + "," + std::to_string(r.dst) + "," + r.channel + "," + r.type +
         "," + std::to_string(r.payload_bytes) + "," + std::to_string(r.wire_bytes) + "," +
         (r.dropped ? "1" : "0") + "," + Network(r.key.network) + "," + r.role;
}

std::string CsvRow(const RadioRow& r) {
  std::string out = Key(r.key) + "," + std::to_string(r.delivered_copies) + "," + FormatDouble(r.mean_hops) + "," +
                    std::to_string(r.max_hops) + "," + std::to_string(r.relay_transmissions) + "," +
                    std::to_string(r.relay_bytes) + "," + std::to_string(r.held_copies) + "," +
                    std::to_string(r.routing_transmissions) + "," + std::to_string(r.routing_bytes);
  for (const std::int64_t d : r.dropped) out += "," + std::to_string(d);
  out += "," + Network(r.key.network) + ",";
  for (std::size_t k = 0; k < r.delivered_by_hops.size(); ++k) {
    out += (k ? " " : "") + std::to_string(r.delivered_by_hops[k]);
  }
  return out;
}

std::string CsvRow(const MediumRow& r) {
  std::string out = Key(r.key) + "," + std::to_string(r.delivered_copies) + "," + std::to_string(r.attempts) + "," +
                    std::to_string(r.backoffs) + "," + std::to_string(r.collisions) + "," +
                    std::to_string(r.retries) + "," + std::to_string(r.airtime_ns) + "," +
                    std::to_string(r.busy_ns) + "," + FormatDouble(r.utilisation);
  for (const std::int64_t d : r.dropped) out += "," + std::to_string(d);
  return out + "," + Network(r.key.network);
}

std::string PerRobotHeader(bool radio, bool mac) {
  return std::string(kPerRobotHeader) +
         (radio ? ",relay_transmissions,relay_bytes,routing_transmissions,routing_bytes" : "") +
         (mac ? ",mac_attempts,mac_backoffs,mac_collisions,mac_retries,mac_dropped_queue_full,"
                "mac_dropped_retry_limit,airtime_share"
              : "");
}

std::string CsvRow(const RobotLoadRow& r, bool radio, bool mac) {
  std::string out = CsvRow(r);
  if (radio) {
    out += "," + std::to_string(r.relay_transmissions) + "," + std::to_string(r.relay_bytes) + "," +
           std::to_string(r.routing_transmissions) + "," + std::to_string(r.routing_bytes);
  }
  if (mac) {
    out += "," + std::to_string(r.mac_attempts) + "," + std::to_string(r.mac_backoffs) + "," +
           std::to_string(r.mac_collisions) + "," + std::to_string(r.mac_retries) + "," +
           std::to_string(r.mac_dropped_queue_full) + "," + std::to_string(r.mac_dropped_retry_limit) + "," +
           FormatDouble(r.airtime_share);
  }
  return out;
}

std::string MessagesHeader(bool radio) { return std::string(kMessagesHeader) + (radio ? ",hops" : ""); }

std::string CsvRow(const MessageRow& r, bool radio) {
  std::string out = CsvRow(r);
  if (radio) out += "," + std::to_string(r.hops);
  return out;
}

std::string QueriesHeader(bool radio) { return std::string(kQueriesHeader) + (radio ? ",hops" : ""); }

std::string CsvRow(const QueryRow& r, bool radio) {
  std::string out = CsvRow(r);
  if (radio) out += "," + Opt(r.hops);
  return out;
}

std::string CsvRow(const BowRow& r) {
  const auto ratio = [](std::int64_t a, std::int64_t b) {
    return b > 0 ? static_cast<double>(a) / static_cast<double>(b) : kNotApplicable;
  };
  std::ostringstream s;
  s << Key(r.key) << ',' << r.queries << ',' << r.partial_queries << ',' << r.payload_bytes << ','
    << FormatDouble(ratio(r.payload_bytes, r.queries)) << ',' << FormatDouble(r.mean_words) << ','
    << FormatDouble(r.mean_part_words) << ',' << r.part_bytes_p50 << ',' << r.part_bytes_p90 << ','
    << r.part_bytes_max << ',' << r.voted << ',' << r.vote_not_centralized << ','
    << FormatDouble(ratio(r.vote_not_centralized, r.voted)) << ',' << Network(r.key.network);
  return s.str();
}

std::string CsvRow(const BowSizeRow& r) {
  return Key(r.key) + "," + std::to_string(r.payload_bytes) + "," + std::to_string(r.messages) + "," +
         Network(r.key.network);
}

void CreateOutputDir(const std::filesystem::path& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir)) {
    throw std::runtime_error(dir.string() + ": cannot create the output folder" +
                             (ec ? " (" + ec.message() + ")" : std::string()));
  }
}

void WriteRunsCsv(const std::filesystem::path& path, const std::vector<RunResult>& rows) {
  AtomicFile f(path);
  f.stream() << kRunsHeader << '\n';
  for (const auto& r : rows) f.stream() << CsvRow(r) << '\n';
  f.Commit();
}

}  // namespace dvpr
