// What a sweep on the radio writes (docs/network_model.md, "The radio"): radio.csv, one row per
// run of a radio variant, with the hops of delivered copies, relaying and drops by reason; the
// radio columns at the end of per_robot.csv (relay_transmissions, relay_bytes) and messages.csv
// (hops). The three files are written from different counters (the network's RouteCounters, each
// robot's NodeCounters, one record per copy), so each is checked against the others, and the
// full-mesh variant of the same sweep against what one hop means. Without a radio nothing
// changes (tests/golden).
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/test_support.h"

namespace {

using dvpr::testing_support::RunProgram;
using dvpr::testing_support::Slurp;

namespace fs = std::filesystem;

using Row = std::map<std::string, std::string>;

std::vector<std::string> Split(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream s(line);
  std::string field;
  while (std::getline(s, field, ',')) out.push_back(field);
  if (!line.empty() && line.back() == ',') out.emplace_back();
  return out;
}

// The CSV's header and its rows by column name.
std::pair<std::string, std::vector<Row>> ReadCsvWithHeader(const fs::path& file) {
  std::stringstream in(Slurp(file));
  std::string header;
  std::getline(in, header);
  const std::vector<std::string> names = Split(header);
  std::vector<Row> rows;
  for (std::string line; std::getline(in, line);) {
    const std::vector<std::string> fields = Split(line);
    EXPECT_EQ(fields.size(), names.size()) << file << ": " << line;
    Row row;
    for (std::size_t i = 0; i < names.size() && i < fields.size(); ++i) row[names[i]] = fields[i];
    rows.push_back(std::move(row));
  }
  return {header, rows};
}

bool EndsWith(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

std::string RunKey(const Row& r) { return r.at("strategy") + "/" + r.at("network_variant"); }

class RadioOutputsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = dvpr::testing_support::FreshTestDir("radio_outputs");
  }
  // 1200 frames of KITTI 00 for 4 robots (300 each, all at once) on 200 m radios with
  // shortest-path relays, beside the full mesh: variant 0 point_to_point, variant 1 the radio.
  fs::path Run(const std::vector<std::string>& extra_sets = {}) {
    const fs::path out = dir_ / "out";
    std::vector<std::string> argv{std::string(DVPR_BINARY_DIR) + "/dvpr", "run",
                                  std::string(DVPR_SOURCE_DIR) + "/experiments/configs/radio_kitti00.yaml",
                                  "--quiet", "--out", out.string()};
    for (const char* set : {"dataset.frames=1200", "evaluation.suppression_frames=50", "robots=[4]", "runs=1",
                            "training.synthetic.samples=2000", "outputs.figures=false", "outputs.messages=true",
                            "network.radio.range=200m"}) {
      argv.insert(argv.end(), {"--set", set});
    }
    for (const std::string& set : extra_sets) argv.insert(argv.end(), {"--set", set});
    const int status = RunProgram(argv, dir_ / "run.log");
    EXPECT_EQ(status, 0) << Slurp(dir_ / "run.log");
    return out;
  }
  fs::path dir_;
};

TEST_F(RadioOutputsTest, RadioCsvPerRobotAndMessagesAgree) {
  const fs::path out = Run({"network.routing=shortest_path"});
  const auto [radio_header, radio] = ReadCsvWithHeader(out / "radio.csv");
  EXPECT_EQ(radio_header,
            "protocol,strategy,robots,run,delivered_copies,mean_hops,max_hops,relay_transmissions,relay_bytes,"
            "held_copies,routing_transmissions,routing_bytes,dropped_queue_full,dropped_loss,dropped_offline,"
            "dropped_no_route,dropped_out_of_range,dropped_hop_limit,dropped_buffer_full,dropped_expired,"
            "dropped_stale_route,dropped_retry_limit,dropped_collision,network_variant,network_model,bandwidth_bps,latency_ms,loss,network_name,"
            "delivered_by_hops");
  // One row per strategy of the radio variant; the full mesh has none.
  ASSERT_EQ(radio.size(), 2u);
  for (const Row& r : radio) EXPECT_EQ(r.at("network_model"), "radio");

  const auto [robot_header, robots] = ReadCsvWithHeader(out / "per_robot.csv");
  EXPECT_TRUE(EndsWith(robot_header, ",network_name,relay_transmissions,relay_bytes,routing_transmissions,routing_bytes"))
      << robot_header;
  const auto [message_header, messages] = ReadCsvWithHeader(out / "messages.csv");
  EXPECT_TRUE(EndsWith(message_header, ",role,hops")) << message_header;

  // Per run: what the robots relayed sums to radio.csv's relaying; messages.csv's delivered
  // copies and their hops give its delivered_copies, mean and max hops; its dropped copies its
  // drops (every reason's column summed).
  std::map<std::string, long long> relay_tx, relay_bytes, delivered, hops, max_hops, dropped, messages_seen;
  std::map<std::string, std::map<long long, long long>> by_hops;  // delivered copies by their hops
  for (const Row& r : robots) {
    relay_tx[RunKey(r)] += std::stoll(r.at("relay_transmissions"));
    relay_bytes[RunKey(r)] += std::stoll(r.at("relay_bytes"));
  }
  for (const Row& m : messages) {
    const std::string key = RunKey(m);
    ++messages_seen[key];
    const long long h = std::stoll(m.at("hops"));
    if (m.at("dropped") == "1") {
      ++dropped[key];
    } else if (!m.at("delivered_ns").empty()) {
      ++delivered[key];
      ++by_hops[key][h];
      hops[key] += h;
      max_hops[key] = std::max(max_hops[key], h);
      if (m.at("network_model") == "point_to_point") {
        EXPECT_EQ(h, 1) << "one hop on the full mesh";
      } else {
        EXPECT_GE(h, 1);
      }
    }
  }
  long long relayed_somewhere = 0;
  for (const Row& r : radio) {
    const std::string key = RunKey(r);
    SCOPED_TRACE(key);
    ASSERT_GT(messages_seen[key], 0);
    EXPECT_EQ(std::stoll(r.at("relay_transmissions")), relay_tx[key]);
    EXPECT_EQ(std::stoll(r.at("relay_bytes")), relay_bytes[key]);
    EXPECT_EQ(std::stoll(r.at("delivered_copies")), delivered[key]);
    EXPECT_EQ(std::stoll(r.at("max_hops")), max_hops[key]);
    EXPECT_DOUBLE_EQ(std::stod(r.at("mean_hops")), static_cast<double>(hops[key]) / delivered[key]);
    // delivered_by_hops: the copies that took 1, 2, ... max_hops hops, as messages.csv counts them.
    std::string histogram;
    for (long long h = 1; h <= max_hops[key]; ++h) {
      histogram += (h > 1 ? " " : "") + std::to_string(by_hops[key][h]);
    }
    EXPECT_EQ(r.at("delivered_by_hops"), histogram);
    long long by_reason = 0;
    for (const char* reason :
         {"queue_full", "loss", "offline", "no_route", "out_of_range", "hop_limit", "buffer_full", "expired",
          "stale_route", "retry_limit", "collision"}) {
      by_reason += std::stoll(r.at(std::string("dropped_") + reason));
    }
    EXPECT_EQ(by_reason, dropped[key]);
    EXPECT_EQ(r.at("dropped_offline"), "0");   // no dropout in this config
    EXPECT_EQ(r.at("dropped_hop_limit"), "0");  // shortest paths do not loop
    EXPECT_EQ(r.at("held_copies"), "0");        // disconnected: drop (the default)
    EXPECT_EQ(r.at("dropped_stale_route"), "0");  // shortest paths are the true graph's
    EXPECT_EQ(r.at("routing_bytes"), "0");        // and send no beacons
    relayed_somewhere += relay_tx[key];
  }
  // 300 frames per robot, 4 robots spread over KITTI 00 at 200 m: some copies need a relay,
  // so hops above 1 and relay bytes appear (docs/network_model.md: 1.3 to 1.9 hops on average).
  EXPECT_GT(relayed_somewhere, 0);
  for (const Row& r : robots) {
    if (r.at("network_model") == "point_to_point") {
      EXPECT_EQ(r.at("relay_transmissions"), "0");
      EXPECT_EQ(r.at("relay_bytes"), "0");
    }
  }
}

// link_state routing beside shortest_path on the same radio (variants 1 and 2): its robots'
// beacons are their routing transmissions (per_robot.csv, summed in radio.csv), they travel on
// DVPR_HELLO and DVPR_TOPOLOGY with the role "other" (messages.csv), and shortest_path sends none.
TEST_F(RadioOutputsTest, LinkStateBeaconsAreTheRobotsRoutingBytes) {
  const fs::path out = Run({"network.routing=[shortest_path, link_state]"});
  const auto [radio_header, radio] = ReadCsvWithHeader(out / "radio.csv");
  ASSERT_EQ(radio.size(), 4u);  // two strategies on two radio variants
  const auto [robot_header, robots] = ReadCsvWithHeader(out / "per_robot.csv");
  std::map<std::string, long long> routing_tx, routing_bytes;
  for (const Row& r : robots) {
    routing_tx[RunKey(r)] += std::stoll(r.at("routing_transmissions"));
    routing_bytes[RunKey(r)] += std::stoll(r.at("routing_bytes"));
  }
  for (const Row& r : radio) {
    const std::string key = RunKey(r);
    SCOPED_TRACE(key);
    EXPECT_EQ(std::stoll(r.at("routing_transmissions")), routing_tx[key]);
    EXPECT_EQ(std::stoll(r.at("routing_bytes")), routing_bytes[key]);
    if (EndsWith(r.at("network_name"), "link_state")) {
      // A beacon is 61 bytes or more (a HELLO listing nobody); one that nobody hears is not sent.
      EXPECT_GT(routing_tx[key], 0);
      EXPECT_GE(routing_bytes[key], 61 * routing_tx[key]);
      EXPECT_GT(std::stoll(r.at("delivered_copies")), 0);
    } else {
      EXPECT_EQ(routing_tx[key], 0);
      EXPECT_EQ(r.at("dropped_stale_route"), "0");
    }
  }
  const auto [message_header, messages] = ReadCsvWithHeader(out / "messages.csv");
  long long beacons = 0;
  for (const Row& m : messages) {
    if (m.at("channel") != "DVPR_HELLO" && m.at("channel") != "DVPR_TOPOLOGY") continue;
    ++beacons;
    EXPECT_TRUE(EndsWith(m.at("network_name"), "link_state")) << m.at("network_name");
    EXPECT_EQ(m.at("role"), "other");
    EXPECT_EQ(m.at("hops"), "1");  // link-local: one hop, never relayed
  }
  EXPECT_GT(beacons, 0);
}

}  // namespace

namespace {

// A query's copies in messages.csv: sent by its robot at its sent_ns on a query channel.
std::string CopyKey(const Row& r, const std::string& robot) {
  return r.at("strategy") + "/" + r.at("network_variant") + "/" + robot + "/" + r.at("sent_ns");
}

}  // namespace

// queries.csv's hops (radio sweeps only): the hops of the query's copy that reached the robot
// whose reply gave the best match, 0 from the robot's own store, empty without a match. Checked
// against messages.csv's copies with what each strategy implies, not with the recorder's logic:
// in broadcast every robot stores only its own frames, so the robot that returned frame F of
// robot m is m (0 hops when m is the querying robot); in decentralized a query goes to one owner
// or, when the robot owns the cluster itself, nowhere (0 hops). Variants: 0 the full mesh (every
// copy one hop), 1 a 100 m radio (copies lost: no reply, no hops), 2 a 200 m radio (relays).
TEST_F(RadioOutputsTest, QueryHopsAreThoseOfTheCopyThatReachedTheAnsweringRobot) {
  const fs::path out =
      Run({"network.routing=shortest_path", "network.radio.range=[100m, 200m]", "outputs.queries=true"});
  const auto [query_header, queries] = ReadCsvWithHeader(out / "queries.csv");
  EXPECT_TRUE(EndsWith(query_header, ",network_name,class,hops")) << query_header;
  const auto [message_header, messages] = ReadCsvWithHeader(out / "messages.csv");
  std::map<std::string, std::vector<Row>> copies;
  for (const Row& m : messages) {
    if (m.at("role") == "query") copies[CopyKey(m, m.at("src"))].push_back(m);
  }
  std::map<std::string, int> checked, relayed, lost;
  for (const Row& q : queries) {
    const std::string variant = q.at("strategy") + "/" + q.at("network_variant");
    SCOPED_TRACE(variant + " robot " + q.at("robot") + " frame " + q.at("frame"));
    const std::vector<Row>& sent = copies[CopyKey(q, q.at("robot"))];
    if (q.at("match_robot").empty()) {
      EXPECT_EQ(q.at("hops"), "");
      continue;
    }
    std::string expected;
    if (q.at("strategy") == "broadcast") {
      ASSERT_EQ(sent.size(), 3u);  // to the 3 others
      if (q.at("match_robot") == q.at("robot")) {
        expected = "0";
      } else {
        for (const Row& c : sent) {
          if (c.at("dst") == q.at("match_robot")) expected = c.at("hops");
        }
      }
    } else {
      ASSERT_LE(sent.size(), 1u);
      expected = sent.empty() ? "0" : sent[0].at("hops");
      if (!sent.empty()) {
        EXPECT_EQ(sent[0].at("dropped"), "0") << "an answer from an owner the query never reached";
      }
    }
    EXPECT_EQ(q.at("hops"), expected);
    ++checked[variant];
    if (q.at("network_variant") == "0") {
      EXPECT_LE(std::stoi(q.at("hops")), 1);
    }
    if (std::stoi(q.at("hops")) >= 2) ++relayed[variant];
  }
  // Decentralized queries whose one copy was lost have no match, hence no hops.
  for (const Row& q : queries) {
    if (q.at("strategy") != "decentralized") continue;
    const std::vector<Row>& sent = copies[CopyKey(q, q.at("robot"))];
    if (sent.size() == 1 && sent[0].at("dropped") == "1") {
      EXPECT_EQ(q.at("hops"), "");
      ++lost[q.at("network_variant")];
    }
  }
  for (const char* v : {"decentralized/0", "decentralized/1", "decentralized/2", "broadcast/0", "broadcast/1",
                        "broadcast/2"}) {
    EXPECT_GT(checked[v], 0) << v;
  }
  EXPECT_GT(relayed["decentralized/2"], 0);
  EXPECT_GT(relayed["broadcast/2"], 0);
  EXPECT_GT(lost["1"], 0);
  EXPECT_EQ(lost["0"], 0);
}
