// The edges of the config: every numeric key's range (one value inside and one outside each
// bound), quantities too large to parse or that round to 0, duplicate keys, a second YAML
// document, a directory, a file key naming something that is not a regular file.
// Every expected line is worked out by hand from docs/config.md.
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "experiments/config/config.h"

namespace dvpr {
namespace {

namespace fs = std::filesystem;

std::string LimitErrorOf(const std::string& yaml, const std::vector<std::string>& sets = {}) {
  std::vector<ConfigOverride> overrides;
  for (const auto& s : sets) overrides.push_back(ParseOverride(s));
  try {
    ParseConfig(yaml, DVPR_SOURCE_DIR, overrides, "test.yaml");
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "(no error)";
}

std::string ErrorOfSet(const std::string& set) { return LimitErrorOf("", {set}); }

// The cases of issue 12: each one line naming the key, its value as written and the range.
TEST(ConfigLimits, TheIssuesQuantitiesAreOneRangeError) {
  EXPECT_EQ(ErrorOfSet("network.latency=999999999999999999999999999999h"),
            "test.yaml: network.latency: must be in [0ns, 24h], got 999999999999999999999999999999h");
  EXPECT_EQ(ErrorOfSet("service.fixed=2562047h"), "test.yaml: service.fixed: must be in [0ns, 24h], got 2562047h");
  EXPECT_EQ(ErrorOfSet("dataset.fps=1e-9"), "test.yaml: dataset.fps: must be in [1, 1000000], got 1e-9");
  EXPECT_EQ(ErrorOfSet("dataset.fps=1e300"), "test.yaml: dataset.fps: must be in [1, 1000000], got 1e300");
  EXPECT_EQ(ErrorOfSet("verification.request_bytes=3000000000"),
            "test.yaml: verification.request_bytes: must be in [0B, 1GiB], got 3000000000");
  // Cut to int this was 25000 bytes.
  EXPECT_EQ(ErrorOfSet("verification.request_bytes=4294992296"),
            "test.yaml: verification.request_bytes: must be in [0B, 1GiB], got 4294992296");
  EXPECT_EQ(LimitErrorOf("network: {links: [{src: 0, dst: 1, latency: 2562047h}]}\n"),
            "test.yaml: network.links[0].latency: must be in [0ns, 24h], got 2562047h");
}

TEST(ConfigLimits, NumbersTooLargeToParseAreRangeErrors) {
  EXPECT_EQ(ErrorOfSet("runs=99999999999999999999999"), "test.yaml: runs: must be in [1, 100000], got 99999999999999999999999");
  EXPECT_EQ(ErrorOfSet("dataset.fps=1e400"), "test.yaml: dataset.fps: must be in [1, 1000000], got 1e400");
  EXPECT_EQ(ErrorOfSet("dataset.fps=1e-400"), "test.yaml: dataset.fps: must be in [1, 1000000], got 1e-400");
  EXPECT_EQ(ErrorOfSet("verification.request_bytes=99999999999999999999999"),
            "test.yaml: verification.request_bytes: must be in [0B, 1GiB], got 99999999999999999999999");
  EXPECT_EQ(ErrorOfSet("verification.request_bytes=9999999999999999999GiB"),
            "test.yaml: verification.request_bytes: must be in [0B, 1GiB], got 9999999999999999999GiB");
  EXPECT_EQ(ErrorOfSet("network.bandwidth=99999999999999999999999Tbps"),
            "test.yaml: network.bandwidth: must be in [1kbps, 1000Gbps], got 99999999999999999999999Tbps");
  EXPECT_EQ(ErrorOfSet("dropout=[{robot: 0, at: 2562048h}]"),
            "test.yaml: dropout[0].at: must be in [0ns, 100000h], got 2562048h");
  // Not a number at all stays a type error.
  EXPECT_EQ(ErrorOfSet("dataset.fps=nan"), "test.yaml: dataset.fps: expected a number, got 'nan'");
}

// Each bound: the bound itself parses, one step past it is refused.
TEST(ConfigLimits, EachRangeAcceptsItsBoundsAndRefusesOnePast) {
  struct Case {
    std::string set;
    std::string error;  // empty: accepted
  };
  const std::vector<Case> cases{
      {"network.latency=24h", ""},
      {"network.latency=86400000000001ns", "network.latency: must be in [0ns, 24h], got 86400000000001ns"},
      {"network.latency=[0ns, 2ms]", ""},
      {"network.bandwidth=1kbps", ""},
      {"network.bandwidth=999bps", "network.bandwidth: must be in [1kbps, 1000Gbps], got 999bps"},
      {"network.bandwidth=1Tbps", ""},
      {"network.bandwidth=1000000000001bps",
       "network.bandwidth: must be in [1kbps, 1000Gbps], got 1000000000001bps"},
      {"network.queue_packets=1073741824", ""},
      {"network.queue_packets=1073741825", "network.queue_packets: must be in [1, 1073741824], got 1073741825"},
      {"network.mtu=68", ""},
      {"network.mtu=67", "network.mtu: must be in [68B, 65535B], got 67"},
      {"network.mtu=65535B", ""},
      {"network.mtu=64KiB", "network.mtu: must be in [68B, 65535B], got 64KiB"},
      {"service.fixed=24h", ""},
      {"service.fixed=24.000000001h", "service.fixed: must be in [0ns, 24h], got 24.000000001h"},
      {"service.per_comparison=1ms", ""},
      {"service.per_comparison=1000001ns", "service.per_comparison: must be in [0ns, 1ms], got 1000001ns"},
      {"verification.request_bytes=1GiB", ""},
      {"verification.request_bytes=1073741825", "verification.request_bytes: must be in [0B, 1GiB], got 1073741825"},
      {"verification.request_bytes=0", ""},
      {"verification.max_distance=3.4028234663852886e38", ""},
      {"verification.max_distance=3.5e38",
       "verification.max_distance: must be in [0, 3.4028234663852886e+38], got 3.5e38"},
      {"dataset.fps=1", ""},
      {"dataset.fps=0.999", "dataset.fps: must be in [1, 1000000], got 0.999"},
      {"dataset.fps=1000000", ""},
      {"dataset.fps=1000000.5", "dataset.fps: must be in [1, 1000000], got 1000000.5"},
      {"dropout=[{robot: 1, at: 100000h}]", ""},
      {"dropout=[{robot: 1, at: 100001h}]", "dropout[0].at: must be in [0ns, 100000h], got 100001h"},
  };
  for (const Case& c : cases) {
    EXPECT_EQ(ErrorOfSet(c.set), c.error.empty() ? "(no error)" : "test.yaml: " + c.error) << c.set;
  }
}

TEST(ConfigLimits, ADuplicateKeyIsAnErrorAtItsLine) {
  EXPECT_EQ(LimitErrorOf("runs: 2\nname: x\nruns: 3\n"), "test.yaml:3: runs: duplicate key (first at line 1)");
  EXPECT_EQ(LimitErrorOf("network:\n  latency: 2ms\n  bandwidth: 1Mbps\n  latency: 3ms\n"),
            "test.yaml:4: network.latency: duplicate key (first at line 2)");
  EXPECT_EQ(LimitErrorOf("robots: [2, 3]\ndropout:\n  - {robot: 1, at: 1s}\n  - {robot: 0, at: 1s, robot: 1}\n"),
            "test.yaml:4: dropout[1].robot: duplicate key (first at line 4)");
  EXPECT_EQ(ErrorOfSet("network={latency: 2ms, latency: 3ms}"),
            "test.yaml: --set network: network.latency: duplicate key");
  // The same key in different maps, and anchors and aliases, are fine.
  EXPECT_EQ(LimitErrorOf("network: {latency: 2ms, links: [{src: 0, dst: 1}, {src: 1, dst: 0}]}\n"
                    "service: {fixed: &t 1ms}\ndropout: [{robot: 1, at: *t}]\n"),
            "(no error)");
}

// The line is where the second document starts: its '---', else its first key.
TEST(ConfigLimits, ASecondDocumentIsAnErrorAtItsLine) {
  EXPECT_EQ(LimitErrorOf("runs: 2\n---\nruns: 3\n"),
            "test.yaml:2: a second YAML document (a config is one document; remove the '---' or '...')");
  EXPECT_EQ(LimitErrorOf("---\nruns: 2\n...\n---\nruns: 3\n"),
            "test.yaml:4: a second YAML document (a config is one document; remove the '---' or '...')");
  EXPECT_EQ(LimitErrorOf("runs: 2\n...\nruns: 3\n"),
            "test.yaml:3: a second YAML document (a config is one document; remove the '---' or '...')");
  EXPECT_EQ(LimitErrorOf("---\nruns: 2\n...\n"), "(no error)");
}

// The radius of ground truth: poses lie within 1e9 m, and position / radius is a grid cell.
TEST(ConfigLimits, TheGroundTruthRadiusKeepsItsSquareAndTheGridCellsRepresentable) {
  EXPECT_EQ(ErrorOfSet("evaluation.gt_radius_m=0.001"), "(no error)");
  EXPECT_EQ(ErrorOfSet("evaluation.gt_radius_m=1e9"), "(no error)");
  EXPECT_EQ(ErrorOfSet("evaluation.gt_radius_m=1e200"),
            "test.yaml: evaluation.gt_radius_m: must be in [0.001, 1000000000], got 1e200");
  EXPECT_EQ(ErrorOfSet("evaluation.gt_radius_m=0.0009"),
            "test.yaml: evaluation.gt_radius_m: must be in [0.001, 1000000000], got 0.0009");
}

// A file key naming a folder says so (it is there, so "not found" would mislead).
TEST(ConfigLimits, AFolderGivenAsAFileIsNamedAsOne) {
  const fs::path dir = fs::path(DVPR_TEST_TMP) / "config_limits_poses_dir";
  fs::create_directories(dir);
  EXPECT_EQ(ErrorOfSet("dataset.poses=" + dir.string()),
            "test.yaml: dataset.poses: '" + dir.string() + "' is a folder, not a regular file");
}

// Issue 53: a FIFO, a device and a loop of symbolic links given as a file were "file not found";
// each is named as what it is under its key, found by stat (the FIFO is never opened: no hang).
// A symbolic link to a regular file is that file.
TEST(ConfigLimits, AFifoADeviceOrALoopOfLinksGivenAsAFileIsNamed) {
  const fs::path dir = fs::path(DVPR_TEST_TMP) / "config_limits_not_regular";
  fs::remove_all(dir);
  fs::create_directories(dir);
  ASSERT_EQ(mkfifo((dir / "fifo").c_str(), 0600), 0);
  fs::create_symlink(dir / "loop_b", dir / "loop_a");
  fs::create_symlink(dir / "loop_a", dir / "loop_b");
  const std::string poses = (dir / "poses.txt").string();
  std::ofstream(poses) << "1 0 0 0 0 1 0 0 0 0 1 0\n1 0 0 1 0 1 0 0 0 0 1 0\n";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {(dir / "fifo").string(), "is a FIFO, not a regular file"},
      {"/dev/zero", "is a device, not a regular file"},
      {(dir / "loop_a").string(), "is a loop of symbolic links"}};
  for (const auto& [path, problem] : cases) {
    EXPECT_EQ(LimitErrorOf("dataset: {trajectories: [{poses: " + path + ", format: tum}]}\n"),
              "test.yaml: dataset.trajectories[0].poses: '" + path + "' " + problem);
    EXPECT_EQ(LimitErrorOf("dataset: {trajectories: [{poses: " + poses + ", format: kitti, times: " + path + "}]}\n"),
              "test.yaml: dataset.trajectories[0].times: '" + path + "' " + problem);
    EXPECT_EQ(ErrorOfSet("dataset.poses=" + path), "test.yaml: dataset.poses: '" + path + "' " + problem);
  }
  // A centroid file of the pattern, for the team of 2 in run 0.
  ASSERT_EQ(mkfifo((dir / "c_n2_r0.npy").c_str(), 0600), 0);
  EXPECT_EQ(LimitErrorOf("robots: [2]\nruns: 1\ntraining: {centroids: '" + (dir / "c_n{robots}_r{run}.npy").string() + "'}\n"),
            "test.yaml: training.centroids: '" + (dir / "c_n2_r0.npy").string() +
                "' is a FIFO, not a regular file (robots 2, run 0)");
  fs::create_symlink(poses, dir / "link.txt");
  EXPECT_EQ(ErrorOfSet("dataset.poses=" + (dir / "link.txt").string()), "(no error)");
}

// Issue 53: a length or duration that is not 0 but rounds to 0 at the parser's resolution (1 mm,
// 1 ns) was "must be in (0m, ...], got 0.4mm", a range that contains it; it says what happened.
TEST(ConfigLimits, AQuantityThatRoundsTo0SaysSoAndNamesTheResolution) {
  EXPECT_EQ(LimitErrorOf("network: {model: radio, radio: {range: 0.4mm}}\n"),
            "test.yaml: network.radio.range: 0.4mm rounds to 0 at the resolution of lengths (1mm), below the smallest "
            "allowed value 1mm");
  EXPECT_EQ(LimitErrorOf("network: {model: radio, radio: {range: [100m, 0.0004m]}}\n"),
            "test.yaml: network.radio.range[1]: 0.0004m rounds to 0 at the resolution of lengths (1mm), below the "
            "smallest allowed value 1mm");
  EXPECT_EQ(LimitErrorOf("network: {model: radio, disconnected: {kind: store_and_forward, hold_time: 0.4ns}}\n"),
            "test.yaml: network.disconnected.hold_time: 0.4ns rounds to 0 at the resolution of durations (1ns), below "
            "the smallest allowed value 1ns");
  EXPECT_EQ(LimitErrorOf("network: {model: radio, radio: {propagation: log_distance, log_distance: {shadowing_window: "
                    "0.0000000001s}}}\n"),
            "test.yaml: network.radio.log_distance.shadowing_window: 0.0000000001s rounds to 0 at the resolution of "
            "durations (1ns), below the smallest allowed value 1ms");
  // Half a unit rounds up to one, which is allowed; 0 as written is still out of the range.
  EXPECT_EQ(LimitErrorOf("network: {model: radio, radio: {range: 0.5mm}}\n"), "(no error)");
  EXPECT_EQ(LimitErrorOf("network: {model: radio, radio: {range: 0m}}\n"),
            "test.yaml: network.radio.range: must be in (0m, 1000000km], got 0m");
  EXPECT_EQ(LimitErrorOf("network: {model: radio, disconnected: {kind: store_and_forward, hold_time: 0ns}}\n"),
            "test.yaml: network.disconnected.hold_time: must be in [1ns, 100000h], got 0ns");
  // Where 0 is allowed, a value that rounds to it is 0 (network.latency is in [0ns, 24h]).
  EXPECT_EQ(LimitErrorOf("network: {latency: 0.4ns}\n"), "(no error)");
}

// A key without a value is an error, not its default (runs: would have run 10 runs).
TEST(ConfigLimits, AKeyWithoutAValueIsAnError) {
  EXPECT_EQ(LimitErrorOf("runs:\n"), "test.yaml: runs: no value given (write one, or leave the key out for its default)");
  EXPECT_EQ(LimitErrorOf("network: {latency: ~}\n"),
            "test.yaml: network.latency: no value given (write one, or leave the key out for its default)");
}

TEST(ConfigLimits, ADirectoryIsNamedAsOne) {
  const fs::path dir = fs::path(DVPR_TEST_TMP) / "config_limits_dir.yaml";
  fs::create_directories(dir);
  try {
    LoadConfig(dir);
    ADD_FAILURE() << "no error";
  } catch (const ConfigError& e) {
    EXPECT_EQ(std::string(e.what()), dir.string() + ": is a directory, expected a YAML config file");
  }
}

}  // namespace
}  // namespace dvpr
