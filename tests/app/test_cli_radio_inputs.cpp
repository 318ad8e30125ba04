// Bad radio inputs through the dvpr binary (issue 33; docs/bad_inputs.md cases g18-g34): a range
// that is not a positive length, an unknown routing, hold sizes out of range, a propagation model
// given another model's keys, a radio whose positions cannot be read, radio keys without a radio.
// Each is one `dvpr: error:` line naming the key and what was expected, exit 1, and nothing
// written: no result folder and no temporary folder beside it.
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "tests/app/cli_test_support.h"

namespace dvpr::testing_support {
namespace {

namespace fs = std::filesystem;

class RadioInputsCliTest : public CliTest {
 protected:
  // 300 frames of KITTI 00 for 3 robots on 200 m radios with shortest-path relays: a config that
  // runs, so every error below is the --set's own.
  std::string Yaml(const std::string& poses = std::string(DVPR_SOURCE_DIR) + "/data/kitti/00_poses.txt") const {
    return "name: radio_inputs\nseed: 1\ndataset: {source: synthetic, poses: '" + poses +
           "', dim: 16, fps: 10, frames: 300}\ntraining: {synthetic: {samples: 500}}\nrobots: [3]\nruns: 1\n"
           "protocols: [sim]\nstrategies: [decentralized, broadcast]\n"
           "evaluation: {gt_radius_m: 5, suppression_frames: 50}\n"
           "network: {model: radio, radio: {propagation: range, range: 200m}, routing: shortest_path}\n"
           "outputs: {figures: false}\n";
  }
  // One error line containing `expected`, exit 1, and the test's folder holds only what was there.
  void ExpectRefused(const std::string& set, const std::string& expected, const std::string& yaml = "") {
    SCOPED_TRACE(set);
    const Result r = RunConfig(yaml.empty() ? Yaml() : yaml, set.empty() ? "" : "--set '" + set + "'");
    ExpectConfigError(r, "bad.yaml: " + expected);
    std::set<std::string> left;
    for (const auto& e : fs::directory_iterator(dir_)) left.insert(e.path().filename().string());
    for (const char* ours : {"bad.yaml", "stdout.txt", "stderr.txt", "poses.txt"}) left.erase(ours);
    EXPECT_TRUE(left.empty()) << *left.begin();
  }
};

TEST_F(RadioInputsCliTest, TheConfigRuns) {
  const Result r = RunConfig(Yaml());
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(fs::exists(Out() / "radio.csv"));
}

TEST_F(RadioInputsCliTest, ARangeThatIsNotAPositiveLength) {
  ExpectRefused("network.radio.range=0m", "network.radio.range: must be in (0m, 1000000km], got 0m");
  ExpectRefused("network.radio.range=-5m", "network.radio.range: expected a length with a unit, e.g. 200m");
  ExpectRefused("network.radio.range=.nan", "network.radio.range: expected a length with a unit, e.g. 200m");
  ExpectRefused("network.radio.range=nanm", "network.radio.range: expected a length with a unit, e.g. 200m");
  ExpectRefused("network.radio.range=200", "network.radio.range: expected a length with a unit, e.g. 200m");
  ExpectRefused("network.radio.range=[100m, 0m]", "network.radio.range[1]: must be in (0m, 1000000km], got 0m");
}

TEST_F(RadioInputsCliTest, AnUnknownRoutingOrBadPeriods) {
  ExpectRefused("network.routing=flooding",
                "network.routing: unknown value 'flooding' (expected one of: direct, shortest_path, link_state)");
  ExpectRefused("network.routing={kind: link_state, hello: 0s}", "network.routing.hello: must be in [1ns, 1h], got 0s");
  ExpectRefused("network.routing={kind: aodv}", "network.routing.kind: unknown value 'aodv'");
}

TEST_F(RadioInputsCliTest, HoldSizesOutOfRange) {
  ExpectRefused("network.disconnected={kind: store_and_forward, hold_bytes: 0B}",
                "network.disconnected.hold_bytes: must be in [1B, 1024GiB], got 0B");
  ExpectRefused("network.disconnected={kind: store_and_forward, hold_bytes: 2048GiB}",
                "network.disconnected.hold_bytes: must be in [1B, 1024GiB], got 2048GiB");
  ExpectRefused("network.disconnected={kind: store_and_forward, hold_bytes: -1MB}",
                "network.disconnected.hold_bytes: expected a size with a unit");
  ExpectRefused("network.disconnected={kind: store_and_forward, hold_bytes: 10}",
                "network.disconnected.hold_bytes: expected a size with a unit");
  ExpectRefused("network.disconnected={kind: store_and_forward, hold_time: 0s}",
                "network.disconnected.hold_time: must be in [1ns, 100000h], got 0s");
  ExpectRefused("network.disconnected={kind: teleport}",
                "network.disconnected.kind: unknown value 'teleport' (expected one of: drop, store_and_forward)");
}

// Every key of a propagation model has a default (ns-3's for log_distance, 200 m for range), so a
// model named without keys runs; a model given the other model's keys, or a key out of its range,
// is refused.
TEST_F(RadioInputsCliTest, APropagationModelGivenAnotherModelsKeys) {
  ExpectRefused("network.radio={propagation: log_distance, range: 200m}",
                "network.radio.range: applies to propagation range; log_distance's reach follows from its own keys");
  ExpectRefused("network.radio={propagation: range, log_distance: {exponent: 3}}",
                "network.radio.log_distance: applies to propagation log_distance, not range");
  ExpectRefused("network.radio={propagation: log_distance, log_distance: {sensitivity_dbm: .nan}}",
                "network.radio.log_distance.sensitivity_dbm: expected a number, got '.nan'");
  ExpectRefused("network.radio={propagation: log_distance, log_distance: {exponent: 0.5}}",
                "network.radio.log_distance.exponent: must be in [1, 10], got 0.5");
  ExpectRefused("network.radio={propagation: two_ray}",
                "network.radio.propagation: unknown value 'two_ray' (expected one of: range, log_distance)");
}

// The radio places each robot on its poses: a pose that cannot be read leaves a position unknown,
// and is refused as for any run, naming the file and line.
TEST_F(RadioInputsCliTest, APositionThatCannotBeKnown) {
  std::ofstream poses(dir_ / "poses.txt");
  for (int i = 0; i < 300; ++i) poses << (i == 8 ? "1 0 0 nan 0 1 0 0 0 0 1 0\n" : "1 0 0 0 0 1 0 0 0 0 1 0\n");
  poses.close();
  ExpectRefused("", "dataset.poses: " + (dir_ / "poses.txt").string() + ": line 9: NaN or Inf: 'nan'",
                Yaml((dir_ / "poses.txt").string()));
  // A pose file shorter than the frames asked for leaves the last robots without positions.
  std::ofstream(dir_ / "poses.txt") << "1 0 0 0 0 1 0 0 0 0 1 0\n";
  ExpectRefused("", "dataset.frames: 300 frames requested, but the pose file " + (dir_ / "poses.txt").string() +
                        " has only 1", Yaml((dir_ / "poses.txt").string()));
}

TEST_F(RadioInputsCliTest, RadioKeysWithoutARadio) {
  ExpectRefused("network.model=point_to_point", "network.radio: applies to model radio, which network.model does not list");
  const std::string p2p = "name: p2p\nrobots: [3]\nruns: 1\nprotocols: [sim]\nnetwork: {model: point_to_point}\n";
  ExpectRefused("network.routing=shortest_path", "network.routing: applies to model radio", p2p);
  ExpectRefused("network.disconnected=store_and_forward", "network.disconnected: applies to model radio", p2p);
  ExpectRefused("outputs.connectivity=true", "outputs.connectivity: needs a network variant of model radio", p2p);
}

}  // namespace
}  // namespace dvpr::testing_support
