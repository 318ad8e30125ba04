// What a sweep on a contending medium writes (docs/network_model.md, "Contending media"):
// medium.csv, one row per run of a csma or wifi variant, and each robot's MAC columns at the end
// of per_robot.csv; contention.png beside the ideal bus. The per-robot counters and the per-run
// row come from different places (each station's MacCounters, the medium's busy time), so they
// are checked against each other and against what each model is: ns-3's CSMA never collides or
// retries and holds the bus for each frame's transmission plus the channel delay.
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/test_support.h"

namespace {

namespace fs = std::filesystem;
using dvpr::testing_support::ReadCsv;
using dvpr::testing_support::Row;
using dvpr::testing_support::RunProgram;
using dvpr::testing_support::Slurp;

std::string Key(const Row& r) { return r.at("strategy") + "/" + r.at("network_variant"); }
std::int64_t Int(const Row& r, const std::string& column) { return std::stoll(r.at(column)); }

TEST(MacOutputsTest, MediumCsvAndPerRobotColumnsAgree) {
  const fs::path dir = dvpr::testing_support::FreshTestDir("mac_outputs");
  const fs::path out = dir / "out";
  // 4 robots, 600 frames of KITTI 00 at 10 fps, both strategies, on one 6 Mbit/s channel three
  // ways: variant 0 the ideal bus, 1 csma (2 ms channel delay), 2 wifi at 6 Mbit/s.
  std::vector<std::string> argv{std::string(DVPR_BINARY_DIR) + "/dvpr", "run",
                                std::string(DVPR_SOURCE_DIR) + "/experiments/configs/bandwidth_scaling.yaml",
                                "--quiet", "--out", out.string()};
  for (const char* set : {"dataset.frames=600", "robots=[4]", "runs=1", "training.synthetic.samples=2000",
                          "network.model=[shared_medium, csma, wifi]", "network.bandwidth=6Mbps",
                          "network.wifi.rate=6Mbps", "outputs.figures=true"}) {
    argv.insert(argv.end(), {"--set", set});
  }
  ASSERT_EQ(RunProgram(argv, dir / "run.log"), 0) << Slurp(dir / "run.log");

  const std::vector<Row> medium = ReadCsv(out / "medium.csv");
  const std::vector<Row> robots = ReadCsv(out / "per_robot.csv");
  // One medium.csv row per strategy of the two contending variants; the ideal bus has none.
  ASSERT_EQ(medium.size(), 4u);
  std::map<std::string, std::map<std::string, std::int64_t>> summed;  // per run: the robots' counters
  std::map<std::string, double> airtime_share;
  for (const Row& r : robots) {
    for (const char* c : {"mac_attempts", "mac_backoffs", "mac_collisions", "mac_retries"}) summed[Key(r)][c] += Int(r, c);
    if (r.at("network_model") == "shared_medium") {
      EXPECT_EQ(r.at("mac_attempts"), "0");
      EXPECT_EQ(r.at("airtime_share"), "") << "the ideal bus has no medium access to count";
    } else {
      airtime_share[Key(r)] += std::stod(r.at("airtime_share"));
    }
  }
  for (const Row& m : medium) {
    const std::string key = Key(m);
    SCOPED_TRACE(key);
    EXPECT_EQ(Int(m, "attempts"), summed[key]["mac_attempts"]);
    EXPECT_EQ(Int(m, "backoffs"), summed[key]["mac_backoffs"]);
    EXPECT_EQ(Int(m, "collisions"), summed[key]["mac_collisions"]);
    EXPECT_EQ(Int(m, "retries"), summed[key]["mac_retries"]);
    EXPECT_GT(Int(m, "attempts"), 600) << "at least one frame per query";
    const double utilisation = std::stod(m.at("medium_utilisation"));
    EXPECT_GT(utilisation, 0.0);
    EXPECT_LE(utilisation, 1.0);
    // The robots' airtime shares add up to the medium's airtime over the same simulated time.
    EXPECT_NEAR(airtime_share[key], utilisation * static_cast<double>(Int(m, "airtime_ns")) /
                                        static_cast<double>(Int(m, "busy_ns")), 1e-9);
    if (m.at("network_model") == "csma") {
      // ns-3's CSMA: no collisions, no retries, and the bus busy for every frame's transmission
      // plus the 2 ms the channel holds it while the frame propagates.
      EXPECT_EQ(Int(m, "collisions"), 0);
      EXPECT_EQ(Int(m, "retries"), 0);
      EXPECT_EQ(Int(m, "busy_ns"), Int(m, "airtime_ns") + Int(m, "attempts") * 2'000'000);
      EXPECT_EQ(Int(m, "dropped_retry_limit") + Int(m, "dropped_collision"), 0);
    } else {
      ASSERT_EQ(m.at("network_model"), "wifi");
      // Every robot's frames on one full mesh: what was retried had collided first, and each
      // DCF procedure draws one backoff (unicast and broadcast alike).
      EXPECT_LE(Int(m, "retries"), Int(m, "collisions"));
      EXPECT_GE(Int(m, "backoffs"), Int(m, "attempts") - Int(m, "retries"));
      EXPECT_EQ(Int(m, "dropped_out_of_range"), 0) << "the full mesh: every robot hears every other";
    }
  }
  EXPECT_TRUE(fs::exists(out / "figures" / "contention.png")) << Slurp(dir / "run.log");
}

// wifi over the radio (network.wifi.propagation: radio): carrier sense and reception follow the
// range. 4 robots on 1200 frames of KITTI 00 are farther than 100 m apart, so at 100 m no copy
// arrives: every unicast frame goes 7 times unanswered (6 retries each) and is lost out of range,
// and every broadcast query is lost out of range at its 3 destinations; at 200 m some arrive.
TEST(MacOutputsTest, WifiOverTheRadioLosesWhatNoRobotInRangeHears) {
  const fs::path dir = dvpr::testing_support::FreshTestDir("mac_outputs");
  const fs::path out = dir / "out";
  std::vector<std::string> argv{std::string(DVPR_BINARY_DIR) + "/dvpr", "run",
                                std::string(DVPR_SOURCE_DIR) + "/experiments/configs/contention.yaml",
                                "--quiet", "--out", out.string()};
  for (const char* set : {"dataset.frames=1200", "robots=[4]", "runs=1", "training.synthetic.samples=2000",
                          "network.model=wifi", "network.wifi={rate: 54Mbps, propagation: radio}",
                          "network.radio.range=[100m, 200m]", "outputs.figures=false", "outputs.messages=true"}) {
    argv.insert(argv.end(), {"--set", set});
  }
  ASSERT_EQ(RunProgram(argv, dir / "run.log"), 0) << Slurp(dir / "run.log");
  const std::vector<Row> medium = ReadCsv(out / "medium.csv");
  ASSERT_EQ(medium.size(), 4u);  // two strategies on two ranges
  std::map<std::string, std::int64_t> dropped_rows;  // messages.csv's dropped copies per run
  for (const Row& m : ReadCsv(out / "messages.csv")) dropped_rows[Key(m)] += m.at("dropped") == "1" ? 1 : 0;
  for (const Row& m : medium) {
    const std::string key = Key(m);
    SCOPED_TRACE(key);
    std::int64_t drops = 0;
    for (const auto& [column, value] : m) {
      if (column.rfind("dropped_", 0) == 0) drops += std::stoll(value);
    }
    EXPECT_EQ(drops, dropped_rows[key]);
    if (m.at("network_name").find("range 100m") != std::string::npos) {
      EXPECT_EQ(Int(m, "delivered_copies"), 0);
      EXPECT_EQ(Int(m, "collisions"), 0) << "no frame reaches anyone: nothing to collide at";
      EXPECT_GT(Int(m, "dropped_out_of_range"), 0);
      if (m.at("strategy") == "decentralized") {
        // Queries and replies only (no match, no verification), one frame each, all unicast.
        EXPECT_EQ(Int(m, "retries"), 6 * Int(m, "dropped_out_of_range"));
        EXPECT_EQ(Int(m, "attempts"), 7 * Int(m, "dropped_out_of_range"));
      } else {
        // One broadcast frame per query, never retried, lost at its 3 destinations.
        EXPECT_EQ(Int(m, "retries"), 0);
        EXPECT_EQ(Int(m, "dropped_out_of_range"), 3 * Int(m, "attempts"));
      }
    } else {
      EXPECT_GT(Int(m, "delivered_copies"), 0);
    }
  }
}

}  // namespace
