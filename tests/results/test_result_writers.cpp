// Result files: exact CSV formatting, atomic writes, summary means, runs.csv read back.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "experiments/results/result_writers.h"
#include "tests/test_support.h"

namespace dvpr {
namespace {

using dvpr::testing_support::Slurp;

namespace fs = std::filesystem;

RunResult SimRow(int run, double rel) {
  RunResult r;
  r.key = RunKey{.protocol = "sim", .strategy = "decentralized", .robots = 4, .run = run,
                 .network = NetworkLabel{.variant = 1, .model = "point_to_point",
                                         .bandwidth_bps = 1e6, .latency_ms = 5, .loss = "none"}};
  r.seed = 99;
  r.auc = 0.5;
  r.auc_reference = 0.625;
  r.relative_auc = rel;
  r.worst_balance_ratio = 2.0 / 3.0;
  r.queries = 100;
  r.messages = 200;
  r.payload_bytes = 51700;
  r.wire_bytes = 54700;
  r.bytes_per_query = 547;
  r.mean_latency_ms = 9.376;
  r.p99_latency_ms = 12.5;
  r.dropped_messages = 0;
  return r;
}

TEST(ResultWriters, RunsCsvColumnsAndFormatting) {
  EXPECT_EQ(std::string(kRunsHeader).rfind(
                "protocol,strategy,robots,run,seed,auc,auc_reference,relative_auc,"
                "worst_balance_ratio,queries,messages,payload_bytes,wire_bytes,bytes_per_query,"
                "mean_latency_ms,p99_latency_ms,dropped_messages,", 0), 0u);
  EXPECT_EQ(CsvRow(SimRow(0, 0.8)),
            "sim,decentralized,4,0,99,0.5,0.625,0.8,0.6666666666666666,100,200,51700,54700,"
            "547,9.376,12.5,0,1,point_to_point,1e+06,5,none,point-to-point 1 Mbit/s 5 ms,"
            + std::string(3 + 5 * 6 + 11, ','));  // no bytes by role: duration and 33 byte columns empty; no closures
  RunResult paper;
  paper.key.protocol = "paper";
  paper.key.strategy = "decentralized";
  paper.key.robots = 2;
  paper.key.run = 1;
  EXPECT_EQ(CsvRow(paper), "paper,decentralized,2,1,0,,,,,0,0,0,0,,,,0," + std::string(5 + 1 + 3 + 30 + 11, ','));
}

// A team run's closure columns, last: hand-made counts. 17 inter-robot queries of which 3
// recognised, 1 intra of 1, AUCs 29/204 and 1, 3 candidates of which 2 closed (precision 2/3),
// 1 pair closed, first at 30 s.
RunResult WithClosures(RunResult r) {
  RunClosures& c = r.closures.emplace();
  c.inter_queries = 17;
  c.intra_queries = 1;
  c.inter_recognised = 3;
  c.intra_recognised = 1;
  c.inter_auc = 0.125;
  c.intra_auc = 1.0;
  c.inter_candidates = 3;
  c.inter_closures = 2;
  c.pairs_closed = 1;
  c.median_first_closure_ns = 30'000'000'000;
  return r;
}

TEST(ResultWriters, RunsCsvClosureColumns) {
  EXPECT_TRUE(std::string(kRunsHeader)
                  .ends_with(",other_delivered_wire_bytes,inter_queries,intra_queries,inter_recall,intra_recall,"
                             "inter_auc,intra_auc,inter_candidates,inter_closures,closure_precision,pairs_closed,"
                             "median_first_closure_s"))
      << kRunsHeader;
  // 3/17 = 0.17647058823529413 and 2/3 = 0.6666666666666666 (python3's repr).
  const std::string row = CsvRow(WithClosures(SimRow(0, 0.8)));
  EXPECT_TRUE(row.ends_with(",17,1,0.17647058823529413,1,0.125,1,3,2,0.6666666666666666,1,30")) << row;
  // A team run without a relevant query or a candidate: its ratios are not applicable (empty).
  RunResult none = SimRow(1, 0.6);
  none.closures.emplace();
  EXPECT_TRUE(CsvRow(none).ends_with(",0,0,,,,,0,0,,0,")) << CsvRow(none);
  // Read back as written (dvpr plot), the counts behind the ratios included.
  const fs::path dir = fs::path(DVPR_TEST_TMP) / "writers_closures";
  fs::remove_all(dir);
  CreateOutputDir(dir);
  WriteRunsCsv(dir / "runs.csv", {WithClosures(SimRow(0, 0.8)), none, SimRow(2, 0.7)});
  const auto rows = ReadRunsCsv(dir / "runs.csv");
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(CsvRow(rows[0]), row);
  ASSERT_TRUE(rows[0].closures.has_value());
  EXPECT_EQ(rows[0].closures->inter_recognised, 3);
  EXPECT_EQ(rows[0].closures->median_first_closure_ns, 30'000'000'000);
  ASSERT_TRUE(rows[1].closures.has_value());
  EXPECT_FALSE(rows[1].closures->median_first_closure_ns.has_value());
  EXPECT_FALSE(rows[2].closures.has_value());
}

// summary.json: the closure metrics' means (with std and ci95) only for groups that ran a team.
TEST(ResultWriters, SummaryHasClosureMeans) {
  RunResult a = WithClosures(SimRow(0, 0.8));
  RunResult b = WithClosures(SimRow(1, 0.6));
  b.closures->inter_closures = 3;  // precision 1: mean (2/3 + 1) / 2 = 0.8333333333333333 (python3)
  b.closures->median_first_closure_ns = 40'000'000'000;
  const std::string json = SummaryJson({a, b});
  EXPECT_NE(json.find("\"inter_queries\": 17, \"intra_queries\": 1, \"inter_recall\": 0.17647058823529413, "
                      "\"intra_recall\": 1, \"inter_auc\": 0.125, \"intra_auc\": 1, \"inter_candidates\": 3, "
                      "\"inter_closures\": 2.5, \"closure_precision\": 0.8333333333333333, \"pairs_closed\": 1, "
                      "\"median_first_closure_s\": 35"),
            std::string::npos) << json;
  EXPECT_EQ(SummaryJson({SimRow(0, 0.8)}).find("inter_queries"), std::string::npos);
}

// Bytes by role: five columns per role in MessageRole order after the totals; hand-made numbers.
RunResult WithRoles(RunResult r) {
  RunRoleBytes b;
  for (int i = 0; i < kMessageRoles; ++i) {
    const std::int64_t k = 10 * (i + 1);  // role i: payload k, copy wire k + 1, ...
    b.copies[static_cast<std::size_t>(i)] = CopyBytes{k, k + 1, k + 2, k + 3};
    b.medium[static_cast<std::size_t>(i)] = k + 4;
  }
  r.roles = b;
  r.duration_s = 45.5;
  return r;
}

TEST(ResultWriters, RunsCsvBytesByRole) {
  const std::string header = kRunsHeader;
  EXPECT_NE(header.find(",loss,network_name,duration_s,copy_wire_bytes,delivered_payload_bytes,"
                        "delivered_wire_bytes,query_payload_bytes,query_wire_bytes,query_copy_wire_bytes,"
                        "query_delivered_payload_bytes,query_delivered_wire_bytes,reply_payload_bytes,"),
            std::string::npos) << header;
  EXPECT_NE(header.find(",other_copy_wire_bytes,other_delivered_payload_bytes,other_delivered_wire_bytes,inter_queries,"),
            std::string::npos) << header;
  // Totals over roles 10..60: copy wire 11+21+..+61 = 216, delivered payload 222, delivered wire 228.
  const std::string row = CsvRow(WithRoles(SimRow(0, 0.8)));
  EXPECT_NE(row.find(",none,point-to-point 1 Mbit/s 5 ms,45.5,216,222,228,10,14,11,12,13,20,24,21,22,23,"),
            std::string::npos) << row;
  EXPECT_TRUE(row.ends_with(",50,54,51,52,53,60,64,61,62,63" + std::string(11, ','))) << row;  // then no closures
  // runs.csv reads back with its roles (dvpr plot draws from the file).
  const fs::path dir = fs::path(DVPR_TEST_TMP) / "writers_roles";
  fs::remove_all(dir);
  CreateOutputDir(dir);
  WriteRunsCsv(dir / "runs.csv", {WithRoles(SimRow(0, 0.8)), SimRow(1, 0.6)});
  const auto rows = ReadRunsCsv(dir / "runs.csv");
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(CsvRow(rows[0]), row);
  ASSERT_TRUE(rows[0].roles.has_value());
  EXPECT_EQ(rows[0].roles->medium[5], 64);
  EXPECT_FALSE(rows[1].roles.has_value());
}

TEST(ResultWriters, LinksCsvBytesByRole) {
  LinkRow l;
  l.key = SimRow(0, 0.8).key;
  l.src = 1;
  l.dst = 2;
  l.messages = 3;
  l.payload_bytes = 210;
  l.wire_bytes = 216;
  RoleCopyBytes roles{};
  for (int i = 0; i < kMessageRoles; ++i) {
    const std::int64_t k = 10 * (i + 1);
    roles[static_cast<std::size_t>(i)] = CopyBytes{k, k + 1, k + 2, k + 3};
  }
  l.roles = roles;
  EXPECT_EQ(CsvRow(l),
            "sim,decentralized,4,0,1,2,3,210,216,0,1,point_to_point,1e+06,5,none,point-to-point 1 Mbit/s 5 ms,"
            "222,228,10,11,12,13,20,21,22,23,30,31,32,33,40,41,42,43,50,51,52,53,60,61,62,63");
  EXPECT_NE(std::string(kLinksHeader).find(",network_name,delivered_payload_bytes,delivered_wire_bytes,"
                                           "query_payload_bytes,query_wire_bytes,query_delivered_payload_bytes,"),
            std::string::npos);
  MessageRow m;
  m.key = l.key;
  m.channel = "DVPR_MATCH_0";
  m.type = "match_t";
  m.role = "reply";
  EXPECT_TRUE(CsvRow(m).ends_with(",0,0,0,1,point_to_point,1e+06,5,none,point-to-point 1 Mbit/s 5 ms,reply")) << CsvRow(m);
  EXPECT_TRUE(std::string(kMessagesHeader).ends_with(",dropped,network_variant,network_model,bandwidth_bps,latency_ms,"
                                                     "loss,network_name,role"));
}

TEST(ResultWriters, NetworkNamesSayTheirParameters) {
  EXPECT_EQ(NetworkName(NetworkLabel{.variant = 3, .model = "shared_medium", .bandwidth_bps = 1e7,
                                     .latency_ms = 2, .loss = "none"}),
            "shared medium 10 Mbit/s 2 ms");
  EXPECT_EQ(NetworkName(NetworkLabel{.variant = 0, .model = "point_to_point", .bandwidth_bps = 2.5e9,
                                     .latency_ms = 0.5, .loss = "bernoulli"}),
            "point-to-point 2500 Mbit/s 500 us bernoulli loss");
  EXPECT_EQ(NetworkName(NetworkLabel{.variant = 0, .model = "point_to_point", .bandwidth_bps = 64e3,
                                     .latency_ms = 20, .loss = "none"}),
            "point-to-point 64 kbit/s 20 ms");
  EXPECT_EQ(NetworkName(NetworkLabel{}), "");
  const NetworkLabel radio{.variant = 2, .model = "radio", .bandwidth_bps = 1e7, .latency_ms = 2, .loss = "none",
                           .propagation = "range 200m", .range_m = 200, .next_hop = "shortest_path"};
  EXPECT_EQ(NetworkName(radio), "radio 10 Mbit/s 2 ms range 200m shortest_path");
  // A swept queue or MTU is named (two variants never share a name).
  EXPECT_EQ(NetworkName(NetworkLabel{.variant = 1, .model = "point_to_point", .bandwidth_bps = 1e7, .latency_ms = 2,
                                     .loss = "none", .queue_packets = 8, .mtu_bytes = 1500}),
            "point-to-point 10 Mbit/s 2 ms queue 8 packets MTU 1500 B");
  // The replay page's heading: the same parts, separated by commas.
  EXPECT_EQ(NetworkName(radio, NameStyle::kPage), "radio, 10 Mbit/s, 2 ms, range 200m shortest_path");
  EXPECT_EQ(NetworkName(NetworkLabel{.model = "shared_medium", .bandwidth_bps = 1e9, .latency_ms = 0.5,
                                     .loss = "bernoulli"}, NameStyle::kPage),
            "shared medium, 1 Gbit/s, 500 us, loss: bernoulli");
  // The latency in the unit that reads naturally, to the ns: 1 us (not 0.001 ms), 1.5 s; 0 ms.
  const auto latency = [](double ms) {
    return NetworkName(NetworkLabel{.model = "shared_medium", .bandwidth_bps = 6e6, .latency_ms = ms, .loss = "none"});
  };
  EXPECT_EQ(latency(0.001), "shared medium 6 Mbit/s 1 us");
  EXPECT_EQ(latency(0.0125), "shared medium 6 Mbit/s 12.5 us");
  EXPECT_EQ(latency(999.5), "shared medium 6 Mbit/s 999.5 ms");
  EXPECT_EQ(latency(1500), "shared medium 6 Mbit/s 1.5 s");
  EXPECT_EQ(latency(0), "shared medium 6 Mbit/s 0 ms");
  // Not applicable (NaN): ideal has neither rate nor latency, wifi no latency.
  EXPECT_EQ(NetworkName(NetworkLabel{.model = "ideal", .loss = "none"}, NameStyle::kPage), "ideal");
  EXPECT_EQ(NetworkName(NetworkLabel{.model = "wifi", .bandwidth_bps = 6e6, .loss = "none"}, NameStyle::kPage),
            "wifi, 6 Mbit/s");
}

// The propagation and the next hop have no column of their own: runs.csv's network_name shows
// them, and a folder read back takes them, typed, from its config's variants (LabelNetworks),
// never from the name. A row that disagrees with the config's variant is refused.
TEST(ResultWriters, RowsReadBackTakeTheirLabelsFromTheConfigsVariants) {
  const fs::path dir = fs::path(DVPR_TEST_TMP) / "writers_radio";
  fs::remove_all(dir);
  CreateOutputDir(dir);
  RunResult a = SimRow(0, 0.8);
  a.key.network.variant = 0;
  a.key.network.model = "radio";
  a.key.network.propagation = "range 200m";
  a.key.network.range_m = 200;
  a.key.network.next_hop = "shortest_path";
  RunResult b = SimRow(1, 0.6);
  b.key.network.variant = 1;
  b.key.network.model = "radio";
  b.key.network.propagation = "log_distance";
  WriteRunsCsv(dir / "runs.csv", {a, b});
  std::vector<RunResult> rows = ReadRunsCsv(dir / "runs.csv");
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].key.network.propagation, "");  // not in a column
  const std::vector<NetworkLabel> variants = {a.key.network, b.key.network};
  LabelNetworks(rows, variants, dir / "runs.csv");
  EXPECT_EQ(rows[0].key.network.range_m, 200.0);
  EXPECT_EQ(rows[0].key.network.next_hop, "shortest_path");
  EXPECT_EQ(rows[1].key.network.propagation, "log_distance");
  EXPECT_TRUE(std::isnan(rows[1].key.network.range_m));
  EXPECT_EQ(rows[1].key.network.next_hop, "");
  for (std::size_t i = 0; i < 2; ++i) EXPECT_EQ(CsvRow(rows[i]), CsvRow(std::vector<RunResult>{a, b}[i])) << i;
  // A launched team's row (protocol lcm) is on a real network, no variant of the config: kept.
  std::vector<RunResult> launched = {SimRow(0, 0.8)};
  launched[0].key.protocol = "lcm";
  launched[0].key.network = NetworkLabel{.variant = 0, .model = "lcm", .loss = "none"};
  LabelNetworks(launched, variants, dir / "runs.csv");
  EXPECT_EQ(launched[0].key.network.model, "lcm");

  std::vector<RunResult> again = ReadRunsCsv(dir / "runs.csv");
  try {
    LabelNetworks(again, std::vector<NetworkLabel>{a.key.network}, dir / "runs.csv");
    ADD_FAILURE() << "a variant the config does not have was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), (dir / "runs.csv").string() +
                                          ":3: network variant 1, but the config has 1 (is config.yaml the one of this run?)");
  }
  NetworkLabel other = b.key.network;
  other.model = "wifi";
  try {
    LabelNetworks(again, std::vector<NetworkLabel>{a.key.network, other}, dir / "runs.csv");
    ADD_FAILURE() << "a variant of another model was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), (dir / "runs.csv").string() +
                                          ":3: network variant 1 is 'radio 1 Mbit/s 5 ms' here but 'wifi 1 Mbit/s 5 ms "
                                          "log_distance' in the config (is config.yaml the one of this run?)");
  }
}

// radio.csv: the run's key, its hops and relaying, then the drops in kRadioDropReasons' order
// (tests/protocols/sim/test_radio_rows.cpp: DropReason's after kNone).
TEST(ResultWriters, RadioCsvRow) {
  RadioRow r;
  r.key = RunKey{.protocol = "sim", .strategy = "broadcast", .robots = 4, .run = 1,
                 .network = NetworkLabel{.variant = 1, .model = "radio", .bandwidth_bps = 1e7, .latency_ms = 2,
                                         .loss = "none", .propagation = "range 200m", .range_m = 200, .next_hop = "shortest_path"}};
  r.delivered_copies = 8;
  r.mean_hops = 1.5;  // 12 hops over 8 copies
  r.max_hops = 3;
  r.relay_transmissions = 4;
  r.relay_bytes = 2188;
  r.held_copies = 5;
  r.routing_transmissions = 30;
  r.routing_bytes = 1950;
  r.dropped = {0, 0, 1, 2, 3, 0, 4, 6, 7, 8, 9};
  r.delivered_by_hops = {6, 0, 2};  // 6 x 1 + 2 x 3 = 12 hops
  EXPECT_EQ(CsvRow(r),
            "sim,broadcast,4,1,8,1.5,3,4,2188,5,30,1950,0,0,1,2,3,0,4,6,7,8,9,1,radio,1e+07,2,none,"
            "radio 10 Mbit/s 2 ms range 200m shortest_path,6 0 2");
  EXPECT_TRUE(std::string(kRadioHeader).ends_with(",network_name,delivered_by_hops"));
  r.delivered_copies = 0;
  r.mean_hops = kNotApplicable;
  EXPECT_EQ(CsvRow(r).substr(0, 22), "sim,broadcast,4,1,0,,3");
  for (const char* reason : kRadioDropReasons) {
    EXPECT_NE(std::string(kRadioHeader).find(std::string("dropped_") + reason), std::string::npos) << reason;
  }
}

// The radio columns come last, so a reader by position finds every other column where it was.
TEST(ResultWriters, RadioColumnsOnlyWithARadio) {
  EXPECT_EQ(PerRobotHeader(false), kPerRobotHeader);
  EXPECT_EQ(PerRobotHeader(true),
            std::string(kPerRobotHeader) + ",relay_transmissions,relay_bytes,routing_transmissions,routing_bytes");
  EXPECT_EQ(MessagesHeader(false), kMessagesHeader);
  EXPECT_EQ(MessagesHeader(true), std::string(kMessagesHeader) + ",hops");
  EXPECT_EQ(QueriesHeader(false), kQueriesHeader);
  EXPECT_EQ(QueriesHeader(true), std::string(kQueriesHeader) + ",hops");
  RobotLoadRow robot;
  robot.relay_transmissions = 3;
  robot.relay_bytes = 1641;
  robot.routing_transmissions = 12;
  robot.routing_bytes = 777;
  EXPECT_EQ(CsvRow(robot, false), CsvRow(robot));
  EXPECT_EQ(CsvRow(robot, true), CsvRow(robot) + ",3,1641,12,777");
  MessageRow message;
  message.hops = 2;
  EXPECT_EQ(CsvRow(message, false), CsvRow(message));
  EXPECT_EQ(CsvRow(message, true), CsvRow(message) + ",2");
}

// medium.csv: the run's key, the medium access's counters, busy time and utilisation, then the
// drops in kRadioDropReasons' order and the network columns.
TEST(ResultWriters, MediumCsvRow) {
  MediumRow m;
  m.key = RunKey{.protocol = "sim", .strategy = "decentralized", .robots = 10, .run = 0,
                 .network = NetworkLabel{.variant = 2, .model = "wifi", .bandwidth_bps = 5.4e7, .latency_ms = 2,
                                         .loss = "none"}};
  m.delivered_copies = 900;
  m.attempts = 1000;
  m.backoffs = 1010;
  m.collisions = 40;
  m.retries = 30;
  m.airtime_ns = 116'000'000;  // 1000 frames of 116 us
  m.busy_ns = 150'000'000;
  m.utilisation = 0.25;        // 150 ms busy of 600 ms
  m.dropped = {0, 0, 0, 0, 0, 0, 0, 0, 0, 2, 5};
  const std::string row = CsvRow(m);
  EXPECT_EQ(row.substr(0, row.find(",2,wifi,")),
            "sim,decentralized,10,0,900,1000,1010,40,30,116000000,150000000,0.25,0,0,0,0,0,0,0,0,0,2,5");
  // As many columns as the header names.
  const std::string header = kMediumHeader;
  EXPECT_EQ(std::count(row.begin(), row.end(), ','), std::count(header.begin(), header.end(), ','));
  for (const char* reason : kRadioDropReasons) {
    EXPECT_NE(std::string(kMediumHeader).find(std::string("dropped_") + reason), std::string::npos) << reason;
  }
  m.utilisation = kNotApplicable;
  EXPECT_NE(CsvRow(m).find(",150000000,,0,"), std::string::npos);
}

// The MAC columns come after any radio columns; a robot of the ideal bus has no airtime share.
TEST(ResultWriters, MacColumnsOnlyWithAContendingMedium) {
  EXPECT_EQ(PerRobotHeader(false, false), kPerRobotHeader);
  EXPECT_EQ(PerRobotHeader(true, true),
            std::string(kPerRobotHeader) + ",relay_transmissions,relay_bytes,routing_transmissions,routing_bytes,"
                                           "mac_attempts,mac_backoffs,mac_collisions,mac_retries,"
                                           "mac_dropped_queue_full,mac_dropped_retry_limit,airtime_share");
  RobotLoadRow robot;
  EXPECT_EQ(CsvRow(robot, false, true), CsvRow(robot) + ",0,0,0,0,0,0,");
  robot.mac_attempts = 7;
  robot.mac_backoffs = 8;
  robot.mac_collisions = 2;
  robot.mac_retries = 1;
  robot.mac_dropped_queue_full = 3;
  robot.mac_dropped_retry_limit = 4;
  robot.airtime_share = 0.125;
  EXPECT_EQ(CsvRow(robot, false, true), CsvRow(robot) + ",7,8,2,1,3,4,0.125");
  EXPECT_EQ(CsvRow(robot, true, true), CsvRow(robot) + ",0,0,0,0,7,8,2,1,3,4,0.125");
}

// The place-recognition ratio: broadcast over decentralized (query + reply copy wire) per query.
TEST(ResultWriters, SummaryHasTheMeasuredPlaceRecognitionRatio) {
  RunResult dec = WithRoles(SimRow(0, 0.8));  // (11 + 21) / 100 queries = 0.32 bytes per query
  RunResult bro = WithRoles(SimRow(0, 1.0));
  bro.key.strategy = "broadcast";
  bro.roles->copies[0].wire = 301;  // (301 + 21) / 100 = 3.22: ratio 3.22 / 0.32 = 10.0625
  const std::string json = SummaryJson({dec, bro});
  EXPECT_NE(json.find("\"place_recognition_bytes_per_query\": 0.32,"), std::string::npos) << json;
  EXPECT_NE(json.find("\"place_recognition_ratio\": [\n    {\"protocol\": \"sim\", \"robots\": 4, "
                      "\"network_variant\": 1, \"network_name\": \"point-to-point 1 Mbit/s 5 ms\", "
                      "\"broadcast_bytes_per_query\": 3.22, \"decentralized_bytes_per_query\": 0.32, "
                      "\"ratio\": 10.0625, \"n_minus_1\": 3}"),
            std::string::npos) << json;
  EXPECT_NE(json.find("\"query_wire_bytes\": 14,"), std::string::npos);
}

TEST(ResultWriters, QueryRowEmptyFieldsWhenNoMatch) {
  QueryRow q;
  q.key.protocol = "sim";
  q.key.strategy = "broadcast";
  q.key.robots = 3;
  q.robot = 2;
  q.frame = 17;
  q.sent_ns = 1700000000;
  q.relevant = true;
  EXPECT_EQ(CsvRow(q), "sim,broadcast,3,0,2,17,1700000000,,,,,1,0,,,,,,,");
  // The class follows the network's columns: inter, intra, or empty when not relevant.
  q.query_class = "inter";
  EXPECT_EQ(CsvRow(q), "sim,broadcast,3,0,2,17,1700000000,,,,,1,0,,,,,,,inter");
  EXPECT_TRUE(std::string(kQueriesHeader).ends_with(",network_name,class")) << kQueriesHeader;
  // queries.csv of a radio sweep: hops last, empty when no match came back, 0 from the own store.
  EXPECT_EQ(CsvRow(q, false), CsvRow(q));
  EXPECT_EQ(CsvRow(q, true), "sim,broadcast,3,0,2,17,1700000000,,,,,1,0,,,,,,,inter,");
  q.hops = 0;
  EXPECT_EQ(CsvRow(q, true), "sim,broadcast,3,0,2,17,1700000000,,,,,1,0,,,,,,,inter,0");
  q.hops = 3;
  EXPECT_EQ(CsvRow(q, true), "sim,broadcast,3,0,2,17,1700000000,,,,,1,0,,,,,,,inter,3");
}

TEST(ResultWriters, AtomicWriteLeavesNoTemporary) {
  const fs::path dir = fs::path(DVPR_TEST_TMP) / "writers";
  fs::remove_all(dir);
  CreateOutputDir(dir);
  WriteRunsCsv(dir / "runs.csv", {SimRow(0, 0.8), SimRow(1, 0.6)});
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
  EXPECT_EQ(Slurp(dir / "runs.csv"), std::string(kRunsHeader) + "\n" + CsvRow(SimRow(0, 0.8)) +
                                         "\n" + CsvRow(SimRow(1, 0.6)) + "\n");
  {
    AtomicFile f(dir / "half.csv");
    f.stream() << "never committed";
  }
  EXPECT_FALSE(fs::exists(dir / "half.csv"));
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
  const auto rows = ReadRunsCsv(dir / "runs.csv");
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(CsvRow(rows[1]), CsvRow(SimRow(1, 0.6)));
}

// A runs.csv that cannot be read back names its line and column: a field that is not a number
// (line 3's "run", the 4th column), a row with a field missing.
TEST(ResultWriters, ReadRunsCsvErrorsNameLineAndColumn) {
  const fs::path dir = fs::path(DVPR_TEST_TMP) / "writers_read_errors";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string good = CsvRow(SimRow(0, 0.8));
  const auto error_of = [&](const std::string& second_row) {
    std::ofstream(dir / "runs.csv") << kRunsHeader << "\n" << good << "\n" << second_row << "\n";
    try {
      ReadRunsCsv(dir / "runs.csv");
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  // The row with field i (0-based) replaced by text.
  const auto with_field = [&](std::size_t i, const std::string& text) {
    std::size_t begin = 0;
    for (std::size_t k = 0; k < i; ++k) begin = good.find(',', begin) + 1;
    return good.substr(0, begin) + text + good.substr(good.find(',', begin));
  };
  const std::string where = (dir / "runs.csv").string() + ":3: ";
  EXPECT_EQ(error_of(with_field(3, "zz")), where + "run: expected an integer, got 'zz'");
  EXPECT_EQ(error_of(with_field(5, "0.8x")), where + "auc: expected a number, got '0.8x'");
  EXPECT_EQ(error_of(with_field(2, "")), where + "robots: expected an integer, got ''");
  std::ofstream(dir / "runs.csv") << kRunsHeader << "\n" << good << "\n" << good.substr(0, good.size() - 1);
  try {
    ReadRunsCsv(dir / "runs.csv");
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), where + "the file ends inside this line (no line end: a cut file?)");
  }
  const std::string cut = good.substr(0, good.rfind(','));
  EXPECT_EQ(error_of(cut), where + "expected " + std::to_string(std::count(good.begin(), good.end(), ',') + 1) +
                               " fields, got " + std::to_string(std::count(good.begin(), good.end(), ',')) +
                               " (a cut or edited file?)");
}

TEST(ResultWriters, UncreatableFolderNamesThePath) {
  const fs::path file = fs::path(DVPR_TEST_TMP) / "a_file";
  std::ofstream(file) << "x";
  try {
    CreateOutputDir(file / "sub");
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find((file / "sub").string()), std::string::npos);
  }
}

TEST(ResultWriters, SummaryMeansPerGroup) {
  RunResult other = SimRow(0, 1.0);
  other.key.strategy = "broadcast";
  const std::string json = SummaryJson({SimRow(0, 0.8), SimRow(1, 0.6), other});
  EXPECT_NE(json.find("\"strategy\": \"decentralized\", \"robots\": 4, \"network_variant\": 1"),
            std::string::npos) << json;
  EXPECT_NE(json.find("\"runs\": 2"), std::string::npos);
  // (0.8 + 0.6) / 2 is 0.7 in double (python3 agrees); 2/3 keeps all 16 digits.
  EXPECT_NE(json.find("\"relative_auc\": 0.7,"), std::string::npos) << json;
  EXPECT_NE(json.find("\"relative_auc\": 1,"), std::string::npos);
  EXPECT_NE(json.find("\"worst_balance_ratio\": 0.6666666666666666,"), std::string::npos);
  EXPECT_NE(json.find("\"bandwidth_bps\": 1e+06,"), std::string::npos);
}

TEST(ResultWriters, FormatDoubleIsLocaleFree) {
  EXPECT_EQ(FormatDouble(1234567.25), "1234567.25");
  EXPECT_EQ(FormatDouble(-0.0), "0");
  EXPECT_EQ(FormatDouble(kNotApplicable), "");
  EXPECT_EQ(FormatDouble(2.5, 0), "2");  // labels only: round half to even, as to_chars does
  EXPECT_EQ(FormatDouble(0.1234567, 6), "0.123457");
}

// The shortest decimal that reads back to the same double: hand-worked strings (python3's repr
// gives the same digits), then a read-back through from_chars for 20000 bit patterns.
TEST(ResultWriters, FormatDoubleIsShortestRoundTrip) {
  EXPECT_EQ(FormatDouble(0.1), "0.1");
  EXPECT_EQ(FormatDouble(1.0 / 3.0), "0.3333333333333333");
  EXPECT_EQ(FormatDouble(0.1 + 0.2), "0.30000000000000004");
  EXPECT_EQ(FormatDouble(-2.5), "-2.5");
  EXPECT_EQ(FormatDouble(547.0), "547");
  EXPECT_EQ(FormatDouble(1e6), "1e+06");  // shorter than 1000000
  EXPECT_EQ(FormatDouble(1e-7), "1e-07");
  EXPECT_EQ(FormatDouble(5e-324), "5e-324");
  EXPECT_EQ(FormatDouble(1.7976931348623157e308), "1.7976931348623157e+308");
  std::uint64_t bits = 0x9E3779B97F4A7C15ull;
  for (int i = 0; i < 20000; ++i) {
    bits = bits * 6364136223846793005ull + 1442695040888963407ull;
    double v;
    std::memcpy(&v, &bits, sizeof v);
    if (!std::isfinite(v)) continue;
    const std::string s = FormatDouble(v);
    double back = 0;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), back);
    ASSERT_TRUE(ec == std::errc() && end == s.data() + s.size()) << s;
    ASSERT_EQ(back, v == 0.0 ? 0.0 : v) << s;
    ASSERT_LE(s.size(), 24u) << s;
  }
}

}  // namespace
}  // namespace dvpr
