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
std::pair<std::string, std::vector<Row>> ReadCsv(const fs::path& file) {
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
  const auto [radio_header, radio] = ReadCsv(out / "radio.csv");
  EXPECT_EQ(radio_header,
            "protocol,strategy,robots,run,delivered_copies,mean_hops,max_hops,relay_transmissions,relay_bytes,"
            "held_copies,routing_transmissions,routing_bytes,dropped_queue_full,dropped_loss,dropped_offline,"
            "dropped_no_route,dropped_out_of_range,dropped_hop_limit,dropped_buffer_full,dropped_expired,"
            "dropped_stale_route,network_variant,network_model,bandwidth_bps,latency_ms,loss,network_name");
  // One row per strategy of the radio variant; the full mesh has none.
  ASSERT_EQ(radio.size(), 2u);
  for (const Row& r : radio) EXPECT_EQ(r.at("network_model"), "radio");

  const auto [robot_header, robots] = ReadCsv(out / "per_robot.csv");
  EXPECT_TRUE(EndsWith(robot_header, ",network_name,relay_transmissions,relay_bytes,routing_transmissions,routing_bytes"))
      << robot_header;
  const auto [message_header, messages] = ReadCsv(out / "messages.csv");
  EXPECT_TRUE(EndsWith(message_header, ",role,hops")) << message_header;

  // Per run: what the robots relayed sums to radio.csv's relaying; messages.csv's delivered
  // copies and their hops give its delivered_copies, mean and max hops; its dropped copies its
  // drops (every reason's column summed).
  std::map<std::string, long long> relay_tx, relay_bytes, delivered, hops, max_hops, dropped, messages_seen;
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
    long long by_reason = 0;
    for (const char* reason :
         {"queue_full", "loss", "offline", "no_route", "out_of_range", "hop_limit", "buffer_full", "expired",
          "stale_route"}) {
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
  const auto [radio_header, radio] = ReadCsv(out / "radio.csv");
  ASSERT_EQ(radio.size(), 4u);  // two strategies on two radio variants
  const auto [robot_header, robots] = ReadCsv(out / "per_robot.csv");
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
  const auto [message_header, messages] = ReadCsv(out / "messages.csv");
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
