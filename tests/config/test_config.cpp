// The config parser: every error names its key path; overrides; the resolved config round trip.
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "experiments/config/config.h"

namespace dvpr {
namespace {

namespace fs = std::filesystem;

class ConfigTest : public ::testing::Test {
 protected:
  // Parses `yaml` with relative paths resolved against the source tree.
  static ExperimentConfig Parse(const std::string& yaml,
                                const std::vector<ConfigOverride>& overrides = {}) {
    return ParseConfig(yaml, DVPR_SOURCE_DIR, overrides, "test.yaml");
  }
  // The ConfigError message of parsing `yaml`.
  static std::string ErrorOf(const std::string& yaml,
                             const std::vector<ConfigOverride>& overrides = {}) {
    try {
      Parse(yaml, overrides);
    } catch (const ConfigError& e) {
      return e.what();
    }
    return "(no error)";
  }
};

// A name names the output folder: at most 255 bytes (NAME_MAX), refused in one short line naming
// the key (120 000 characters gave a 120 kB line naming neither name nor --out).
TEST_F(ConfigTest, ANameLongerThanAFolderNameIsOneShortLineNamingTheKey) {
  EXPECT_EQ(Parse("name: " + std::string(255, 'n') + "\n").name.size(), 255u);
  const std::string e = ErrorOf("name: " + std::string(120000, 'n') + "\n");
  EXPECT_EQ(e, "test.yaml: name: expected at most 255 bytes (it names the output folder), got 120000");
}

TEST_F(ConfigTest, DefaultsFromAnEmptyMap) {
  const ExperimentConfig c = Parse("name: x\n");
  EXPECT_EQ(c.sweep.robots.size(), 19u);
  EXPECT_EQ(c.sweep.runs, 10);
  EXPECT_EQ(c.network.bandwidth.at(0), DataRate::Mbps(10));
  EXPECT_TRUE(c.dataset.poses.is_absolute());
  EXPECT_TRUE(fs::exists(c.dataset.poses));
}

TEST_F(ConfigTest, DesignExampleParses) {
  const ExperimentConfig c = Parse(R"(
name: paper_kitti00
seed: 1
dataset: {source: synthetic, poses: data/kitti/00_poses.txt, dim: 128, fps: 10, frames: all}
training: {source: synthetic_diverse}
robots: {from: 2, to: 20}
runs: 10
protocols: [paper, sim]
strategies: [decentralized, broadcast]
evaluation: {gt_radius_m: 5, suppression_frames: 250}
network: {model: point_to_point, bandwidth: 10Mbps, latency: 2ms, queue_packets: 100, loss: {model: none}}
verification: {request_bytes: 25000, max_distance: 0.6}
service: {fixed: 50us, per_comparison: 20ns}
outputs: {figures: true, queries: false, messages: false, lcm_log: false}
)");
  EXPECT_EQ(c.sweep.robots.front(), 2);
  EXPECT_EQ(c.sweep.robots.back(), 20);
  EXPECT_EQ(c.agent.verification.request_bytes, Bytes(25000));
  EXPECT_EQ(c.agent.service.per_comparison, SimTime::Nanos(20));
  EXPECT_FALSE(c.dataset.frames.has_value());
}

TEST_F(ConfigTest, UnknownKeyNamesItsPathAndTheExpectedKeys) {
  const std::string e = ErrorOf("network: {bandwith: 10Mbps}\n");
  EXPECT_NE(e.find("test.yaml: network.bandwith: unknown key (expected one of: model, bandwidth"),
            std::string::npos) << e;
  EXPECT_NE(ErrorOf("colour: red\n").find("colour: unknown key"), std::string::npos);
  EXPECT_NE(ErrorOf("network: {loss: {model: bernoulli, p: 0.1, q: 2}}\n")
                .find("network.loss.q: unknown key"), std::string::npos);
}

TEST_F(ConfigTest, WrongTypes) {
  EXPECT_NE(ErrorOf("runs: ten\n").find("runs: expected an integer, got 'ten'"), std::string::npos);
  EXPECT_NE(ErrorOf("dataset: {dim: [1, 2]}\n").find("dataset.dim: expected an integer, got a list"),
            std::string::npos);
  EXPECT_NE(ErrorOf("outputs: {figures: maybe}\n").find("outputs.figures: expected true or false"),
            std::string::npos);
  EXPECT_NE(ErrorOf("network: 5\n").find("network: expected a map"), std::string::npos);
  EXPECT_NE(ErrorOf("protocols: [paper, simulation]\n")
                .find("protocols[1]: unknown value 'simulation' (expected one of: paper, sim)"),
            std::string::npos);
}

TEST_F(ConfigTest, MissingFile) {
  const std::string e = ErrorOf("dataset: {source: files, descriptors: no_such.npy}\n");
  EXPECT_NE(e.find("dataset.descriptors: file not found: 'no_such.npy'"), std::string::npos) << e;
  EXPECT_NE(ErrorOf("dataset: {source: files}\n").find("dataset.descriptors: required"),
            std::string::npos);
  EXPECT_NE(ErrorOf("training: {centroids: 'c_n{robots}_r{run}.npy'}\n")
                .find("training.centroids: file not found"), std::string::npos);
}

TEST_F(ConfigTest, RobotsAndRunsBounds) {
  EXPECT_NE(ErrorOf("robots: [1, 2]\n").find("robots[0]: must be in [2, 100000], got 1"),
            std::string::npos);
  EXPECT_NE(ErrorOf("robots: {from: 1, to: 5}\n").find("robots.from: must be in [2, 100000], got 1"),
            std::string::npos);
  EXPECT_NE(ErrorOf("robots: {from: 5, to: 3}\n").find("robots.to: must be at least robots.from"),
            std::string::npos);
  EXPECT_NE(ErrorOf("runs: 0\n").find("runs: must be in [1, 100000], got 0"), std::string::npos);
}

TEST_F(ConfigTest, UnitsRequired) {
  const std::string e = ErrorOf("network: {bandwidth: 10}\n");
  EXPECT_NE(e.find("network.bandwidth: expected a data rate with a unit, e.g. 10Mbps"),
            std::string::npos) << e;
  EXPECT_NE(ErrorOf("network: {latency: 5}\n").find("network.latency: expected a duration"),
            std::string::npos);
  EXPECT_NE(ErrorOf("network: {bandwidth: [1Mbps, 10]}\n").find("network.bandwidth[1]:"),
            std::string::npos);
  // Plain integers are bytes only where DESIGN shows one.
  EXPECT_EQ(Parse("verification: {request_bytes: 25kB}\n").agent.verification.request_bytes, Bytes(25000));
  EXPECT_EQ(Parse("network: {mtu: 576}\n").network.mtu.at(0), Bytes(576));
}

TEST_F(ConfigTest, StrategiesAreParsedWhenTheConfigIsLoaded) {
  const ExperimentConfig c = Parse("strategies: [broadcast, lpt_c4+multi_probe_2, recluster_c2_p50]\n");
  ASSERT_EQ(c.sweep.strategies.size(), 3u);
  EXPECT_TRUE(c.sweep.strategies[0].broadcast());
  EXPECT_EQ(c.sweep.strategies[1].name, "lpt_c4+multi_probe_2");
  EXPECT_EQ(c.sweep.strategies[1].table, StrategySpec::Table::kLpt);
  EXPECT_EQ(c.sweep.strategies[1].clusters_per_robot, 4);
  EXPECT_EQ(c.sweep.strategies[1].probe.probes, 2);
  EXPECT_EQ(c.sweep.strategies[2].recluster_period, 50);
  // The emitted config names them as written and reads back to the same specs.
  const std::string yaml = EmitConfig(c);
  const std::string line = "strategies: [broadcast, lpt_c4+multi_probe_2, recluster_c2_p50]\n";
  EXPECT_NE(yaml.find(line), std::string::npos) << yaml;
  EXPECT_EQ(Parse(line).sweep.strategies, c.sweep.strategies);
  // Overrides go through the same parser.
  EXPECT_EQ(Parse("", {ParseOverride("strategies=[sample_c2]")}).sweep.strategies.at(0).table,
            StrategySpec::Table::kSampleKMeans);
}

TEST_F(ConfigTest, ABadStrategyNameIsAnErrorAtItsKeyPath) {
  EXPECT_EQ(ErrorOf("strategies: [decentralized, broadcast, multi_probe_x]\n"),
            "test.yaml: strategies[2]: 'multi_probe_x' is not a strategy: M must be a whole number >= 1, got 'x'");
  EXPECT_EQ(ErrorOf("strategies: [decentralized, recluster_c0_p50]\n"),
            "test.yaml: strategies[1]: 'recluster_c0_p50' is not a strategy: C must be a whole number >= 1, got 'c0'");
  EXPECT_NE(ErrorOf("strategies: [lpt_c7, multiprobe_2]\n").find("strategies[1]: 'multiprobe_2' is not a strategy: unknown name"),
            std::string::npos);
  EXPECT_EQ(ErrorOf("strategies: [broadcast, broadcast]\n"), "test.yaml: strategies[1]: listed twice");
  EXPECT_NE(ErrorOf("strategies: {a: 1}\n").find("strategies: expected a value or a list of values, got a map"),
            std::string::npos);
  EXPECT_NE(ErrorOf("", {ParseOverride("strategies=[decentralized, adaptive_probe_0.10]")})
                .find("strategies[1]: 'adaptive_probe_0.10' is not a strategy: E must be written 0.1"),
            std::string::npos);
}

// The sections hold the lower layers' params; their Validate() names the field, the reader the
// key path before it, the same path as for a value the reader itself rejects.
TEST_F(ConfigTest, ParamsErrorsCarryTheKeyPath) {
  const auto starts_with = [](const std::string& error, const std::string& prefix) {
    EXPECT_EQ(error.rfind(prefix, 0), 0u) << error;
  };
  starts_with(ErrorOf("network: {loss: {model: bernoulli, p: 1.5}}\n"),
              "test.yaml: network.loss.p: a probability must lie in [0, 1], got 1.5");
  starts_with(ErrorOf("network: {links: [{src: 0, dst: 1, loss: {model: gilbert_elliott, "
                      "p_good_to_bad: 2, p_bad_to_good: 0.5}}]}\n"),
              "test.yaml: network.links[0].loss.p_good_to_bad: a probability must lie in [0, 1], got 2");
  starts_with(ErrorOf("network: {model: [ideal, token_ring]}\n"),
              "test.yaml: network.model[1]: unknown value 'token_ring' (expected one of: ideal, "
              "point_to_point, shared_medium, radio, csma, wifi)");
  starts_with(ErrorOf("network: {loss: {model: sometimes}}\n"),
              "test.yaml: network.loss.model: unknown value 'sometimes' (expected one of: none, bernoulli, "
              "gilbert_elliott)");
  starts_with(ErrorOf("dataset: {synthetic: {heading_fraction: 1.5}}\n"),
              "test.yaml: dataset.synthetic.heading_fraction: must lie in [0, 1]");
  starts_with(ErrorOf("dataset: {synthetic: {length_scale_max_m: 1}}\n"),
              "test.yaml: dataset.synthetic.length_scale_max_m: must be finite and at least length_scale_min_m");
  starts_with(ErrorOf("training: {synthetic: {training_area_m: 0}}\n"),
              "test.yaml: training.synthetic.training_area_m: must be positive");
  starts_with(ErrorOf("verification: {max_distance: -1}\n"),
              "test.yaml: verification.max_distance: must be in [0, 3.4028234663852886e+38], got -1");
  starts_with(ErrorOf("evaluation: {gt_radius_m: 0}\n"),
              "test.yaml: evaluation.gt_radius_m: must be in [0.001, 1000000000], got 0");
}

// Bag-of-words keys (docs/bow.md): the model is set to its defaults only when a bow_ strategy
// runs, its fields are range-checked with their key path, and dataset.bow must exist.
TEST_F(ConfigTest, BagOfWordsKeys) {
  EXPECT_FALSE(Parse("name: x\n").dataset.synthetic_bow);
  EXPECT_EQ(Parse("strategies: [bow_decentralized]\n").dataset.synthetic_bow, SyntheticBowParams{});
  const ExperimentConfig c = Parse("dataset: {synthetic_bow: {features: 300, vocabulary: 10000}}\n");
  ASSERT_TRUE(c.dataset.synthetic_bow);
  EXPECT_EQ(c.dataset.synthetic_bow->features, 300);
  EXPECT_EQ(c.dataset.synthetic_bow->vocabulary, 10000);
  EXPECT_EQ(ErrorOf("dataset: {synthetic_bow: {vocabulary: 1}}\n").rfind(
                "test.yaml: dataset.synthetic_bow.vocabulary: ", 0), 0u);
  EXPECT_EQ(ErrorOf("dataset: {synthetic_bow: {range_m: 0}}\n"),
            "test.yaml: dataset.synthetic_bow.range_m: must be in (0, 1000]");
  EXPECT_EQ(ErrorOf("dataset: {synthetic_bow: {words: 3}}\n").rfind("test.yaml: dataset.synthetic_bow.words: ", 0), 0u);
  // The aliasing and viewpoint keys (off unless set: common_share 0, view_sector_deg 360).
  const ExperimentConfig w =
      Parse("dataset: {synthetic_bow: {common_words: 50, common_share: 0.25, view_sector_deg: 80}}\n");
  ASSERT_TRUE(w.dataset.synthetic_bow);
  EXPECT_EQ(w.dataset.synthetic_bow->common_words, 50);
  EXPECT_EQ(w.dataset.synthetic_bow->common_share, 0.25);
  EXPECT_EQ(w.dataset.synthetic_bow->view_sector_deg, 80.0);
  EXPECT_EQ(SyntheticBowParams{}.common_share, 0.0);
  EXPECT_EQ(SyntheticBowParams{}.view_sector_deg, 360.0);
  EXPECT_EQ(ErrorOf("dataset: {synthetic_bow: {common_share: 1.5, common_words: 5}}\n"),
            "test.yaml: dataset.synthetic_bow.common_share: must be in [0, 1]");
  EXPECT_EQ(ErrorOf("dataset: {synthetic_bow: {common_share: 0.5}}\n"),
            "test.yaml: dataset.synthetic_bow.common_share: needs common_words >= 1 when above 0");
  EXPECT_EQ(ErrorOf("dataset: {synthetic_bow: {vocabulary: 100, common_words: 100}}\n"),
            "test.yaml: dataset.synthetic_bow.common_words: must be in [0, vocabulary - 1 = 99], got 100");
  EXPECT_EQ(ErrorOf("dataset: {synthetic_bow: {common_words: -1}}\n").rfind(
                "test.yaml: dataset.synthetic_bow.common_words: ", 0), 0u);
  EXPECT_EQ(ErrorOf("dataset: {synthetic_bow: {view_sector_deg: 400}}\n"),
            "test.yaml: dataset.synthetic_bow.view_sector_deg: must be in (0, 360]");
  EXPECT_EQ(ErrorOf("dataset: {bow: no_such_file.txt}\n").rfind("test.yaml: dataset.bow: ", 0), 0u);
}

// verification.bow_max_distance (docs/config.md): 0.95 unless set, in [0, 1]; written back only
// for a config with a bow_ strategy or a value of its own, so other configs' text is unchanged.
TEST_F(ConfigTest, BowVerificationThresholdIsCheckedAndWrittenWhereItMatters) {
  const ExperimentConfig plain = Parse("name: x\n");
  EXPECT_EQ(plain.agent.verification.bow_max_distance, 0.95);
  EXPECT_EQ(EmitConfig(plain).find("bow_max_distance"), std::string::npos) << EmitConfig(plain);
  const ExperimentConfig bow = Parse("strategies: [bow_decentralized]\n");
  EXPECT_NE(EmitConfig(bow).find("max_distance: 0.6, bow_max_distance: 0.95}"), std::string::npos) << EmitConfig(bow);
  const ExperimentConfig set = Parse("verification: {bow_max_distance: 0.5}\n");
  EXPECT_EQ(set.agent.verification.bow_max_distance, 0.5);
  EXPECT_EQ(ParseConfig(EmitConfig(set), "/nonexistent", {}, "config.yaml"), set);
  EXPECT_EQ(ErrorOf("verification: {bow_max_distance: 1.5}\n"),
            "test.yaml: verification.bow_max_distance: must be in [0, 1], got 1.5");
  EXPECT_EQ(ErrorOf("verification: {bow_max_distance: -0.1}\n"),
            "test.yaml: verification.bow_max_distance: must be in [0, 1], got -0.1");
}

// One YAML value that several params structs hold is in each of them.
TEST_F(ConfigTest, SharedValuesReachEveryParamsStruct) {
  const ExperimentConfig c =
      Parse("seed: 9\ndataset: {dim: 16}\nevaluation: {suppression_frames: 40}\n"
            "training: {clusters_per_robot: 3}\nservice: {fixed: 1ms}\n");
  EXPECT_EQ(c.training.run_centroids.seed, 9u);
  EXPECT_EQ(c.training.run_centroids.clusters_per_robot, 3);
  EXPECT_TRUE(c.training.run_centroids.centroids_pattern.empty());
  EXPECT_EQ(c.dataset.synthetic.dim, 16);
  EXPECT_EQ(c.agent.suppression_frames, 40);
  EXPECT_EQ(c.evaluation.suppression_frames, 40);
  EXPECT_EQ(c.agent.service.fixed, SimTime::Millis(1));
  EXPECT_EQ(c.agent.service.per_comparison, SimTime::Nanos(20));  // ServiceParams' default
}

TEST_F(ConfigTest, ErrorsAreOneLine) {
  for (const char* bad : {"network: {bandwith: 1Mbps}\n", "runs: 0\n", "robots: [1]\n",
                          "network: {bandwidth: 10}\n", "dataset: {source: files}\n"}) {
    EXPECT_EQ(ErrorOf(bad).find('\n'), std::string::npos) << bad;
  }
}

TEST_F(ConfigTest, SetOverridesApplyBeforeValidation) {
  const ExperimentConfig c = Parse("runs: 10\nnetwork: {bandwidth: 10Mbps}\n",
                                   {ParseOverride("runs=2"),
                                    ParseOverride("network.bandwidth=[1Mbps, 5Mbps]"),
                                    ParseOverride("robots={from: 3, to: 4}"),
                                    ParseOverride("network.loss.model=bernoulli"),
                                    ParseOverride("network.loss.p=0.25")});
  EXPECT_EQ(c.sweep.runs, 2);
  EXPECT_EQ(c.network.bandwidth, (std::vector<DataRate>{DataRate::Mbps(1), DataRate::Mbps(5)}));
  EXPECT_EQ(c.sweep.robots, (std::vector<int>{3, 4}));
  EXPECT_EQ(c.network.loss.model, LossModelKind::kBernoulli);
  EXPECT_DOUBLE_EQ(c.network.loss.bernoulli.p, 0.25);
  EXPECT_NE(ErrorOf("runs: 2\n", {ParseOverride("runs=0")}).find("runs: must be in [1, 100000], got 0"),
            std::string::npos);
  EXPECT_NE(ErrorOf("", {ParseOverride("network.bandwith=1Mbps")})
                .find("network.bandwith: unknown key"), std::string::npos);
  EXPECT_THROW(ParseOverride("runs"), ConfigError);
}

TEST_F(ConfigTest, ResolvedConfigRoundTrips) {
  const ExperimentConfig c = Parse(R"(
name: rt
seed: 7
dataset: {frames: 300, synthetic: {noise: 0.125}}
robots: [2, 5, 9]
runs: 3
network:
  model: [point_to_point, shared_medium, ideal]
  bandwidth: [1Mbps, 1.5Mbps]
  latency: [5ms, 250us]
  loss: {model: gilbert_elliott, p_good_to_bad: 0.01, p_bad_to_good: 0.3, loss_bad: 0.7}
  links: [{src: 0, dst: 1, bandwidth: 100kbps, latency: 1s}]
dropout: [{robot: 1, at: 12s}]
service: {fixed: 1ms, per_comparison: 7ns}
outputs: {queries: true, pr_robots: 5}
)");
  const std::string yaml = EmitConfig(c);
  const ExperimentConfig again = ParseConfig(yaml, "/nonexistent", {}, "config.yaml");
  EXPECT_EQ(again, c) << yaml;
  EXPECT_EQ(EmitConfig(again), yaml);
}

}  // namespace
}  // namespace dvpr

namespace dvpr {
namespace {

// failover (docs/failover.md): off by default and then not written back, so the config.yaml of a
// run without it reads as before; on, it is written and reads back the same.
TEST_F(ConfigTest, FailoverIsReadCheckedAndWrittenOnlyWhenSet) {
  const ExperimentConfig off = Parse("name: f\n");
  EXPECT_FALSE(off.failover.enabled);
  EXPECT_EQ(off.failover.heartbeat_period, SimTime::Millis(250));
  EXPECT_EQ(off.failover.timeout, SimTime::Seconds(1));
  EXPECT_EQ(EmitConfig(off).find("\nfailover:"), std::string::npos) << EmitConfig(off);

  const ExperimentConfig on = Parse("failover: {enabled: true, heartbeat_period: 40ms, timeout: 300ms}\n");
  EXPECT_TRUE(on.failover.enabled);
  EXPECT_EQ(on.failover.heartbeat_period, SimTime::Millis(40));
  EXPECT_EQ(on.failover.timeout, SimTime::Millis(300));
  const std::string yaml = EmitConfig(on);
  EXPECT_NE(yaml.find("\nfailover: {enabled: true, heartbeat_period: 40ms, timeout: 300ms}\n"), std::string::npos) << yaml;
  EXPECT_EQ(ParseConfig(yaml, "/nonexistent", {}, "config.yaml"), on);
  EXPECT_TRUE(Parse("", {ParseOverride("failover.enabled=true")}).failover.enabled);
}

TEST_F(ConfigTest, FailoverErrorsNameTheKey) {
  EXPECT_EQ(ErrorOf("failover: {timeout: 200ms}\n"),
            "test.yaml: failover.timeout: timeout must be longer than heartbeat_period, got 200ms and 250ms");
  EXPECT_NE(ErrorOf("failover: {heartbeat_period: 0ms}\n").find("test.yaml: failover.heartbeat_period: must be in [1ms, 1h]"),
            std::string::npos);
  EXPECT_NE(ErrorOf("failover: {enabled: yes please}\n").find("test.yaml: failover.enabled:"), std::string::npos);
  EXPECT_NE(ErrorOf("failover: {enable: true}\n").find("test.yaml: failover.enable:"), std::string::npos);
  EXPECT_EQ(ErrorOf("strategies: [decentralized, recluster_c2_p50]\nfailover: {enabled: true}\n"),
            "test.yaml: failover.enabled: 'recluster_c2_p50' re-clusters, which has no failover; list it in a config "
            "without");
}

}  // namespace
}  // namespace dvpr

namespace dvpr {
namespace {

// dataset.trajectories[i].descriptors (issue 50, item 1): with dataset.source files every robot's
// entry names its own descriptor file; an entry without one, a file with the synthetic source, or
// dataset.descriptors beside the trajectories is one error naming the entry; config.yaml keeps the
// files and reads back the same.
class TeamDescriptorKeysTest : public ConfigTest {
 protected:
  void SetUp() override {
    dir_ = fs::path(DVPR_TEST_TMP) / "team_descriptor_keys";
    fs::create_directories(dir_);
    std::ofstream(dir_ / "r0.txt") << "0 0 0 0 0 0 0 1\n1 1 0 0 0 0 0 1\n";
    std::ofstream(dir_ / "r1.txt") << "0 0 0 5 0 0 0 1\n1 1 0 5 0 0 0 1\n";
    std::ofstream(dir_ / "d0.csv") << "1,2\n3,4\n";
    std::ofstream(dir_ / "d1.csv") << "5,6\n7,8\n";
  }
  std::string Team(const std::string& source, const std::string& d0, const std::string& d1,
                   const std::string& extra = "") const {
    const auto entry = [&](const std::string& poses, const std::string& desc) {
      return "{poses: '" + (dir_ / poses).string() + "', format: tum" +
             (desc.empty() ? "" : ", descriptors: '" + (dir_ / desc).string() + "'") + "}";
    };
    return "dataset: {source: " + source + ", dim: 2" + extra + ", trajectories: [" + entry("r0.txt", d0) + ", " +
           entry("r1.txt", d1) + "]}\nrobots: [2]\n";
  }
  fs::path dir_;
};

TEST_F(TeamDescriptorKeysTest, EveryEntryNamesItsOwnFileWithSourceFiles) {
  const ExperimentConfig c = Parse(Team("files", "d0.csv", "d1.csv"));
  ASSERT_EQ(c.dataset.trajectories.size(), 2u);
  EXPECT_EQ(c.dataset.trajectories[1].descriptors, dir_ / "d1.csv");
  EXPECT_FALSE(c.dataset.descriptors);
  const std::string yaml = EmitConfig(c);
  EXPECT_NE(yaml.find("descriptors: " + (dir_ / "d0.csv").string()), std::string::npos) << yaml;
  const ExperimentConfig again = ParseConfig(yaml, "/nonexistent", {}, "config.yaml");
  EXPECT_EQ(again, c) << yaml;
  EXPECT_EQ(EmitConfig(again), yaml);
}

TEST_F(TeamDescriptorKeysTest, AnEntryWithoutAFileOrAFileWithoutSourceFilesIsNamed) {
  EXPECT_EQ(ErrorOf(Team("files", "d0.csv", "")),
            "test.yaml: dataset.trajectories[1].descriptors: required when dataset.source is files: one descriptor "
            "file per robot (an .npy, .bin or .csv file, one row per pose); dataset.trajectories[0] names one, this "
            "entry none");
  EXPECT_EQ(ErrorOf(Team("files", "", "d1.csv")),
            "test.yaml: dataset.trajectories[0].descriptors: required when dataset.source is files: one descriptor "
            "file per robot (an .npy, .bin or .csv file, one row per pose); dataset.trajectories[1] names one, this "
            "entry none");
  EXPECT_EQ(ErrorOf(Team("files", "", "")),
            "test.yaml: dataset.trajectories[0].descriptors: required when dataset.source is files: one descriptor "
            "file per robot (an .npy, .bin or .csv file, one row per pose)");
  EXPECT_EQ(ErrorOf(Team("synthetic", "", "d1.csv")),
            "test.yaml: dataset.trajectories[1].descriptors: a descriptor file of the robot's own needs "
            "dataset.source: files (with synthetic, every robot's descriptors are rendered by the model)");
  EXPECT_EQ(ErrorOf(Team("files", "d0.csv", "d1.csv", ", descriptors: '" + (dir_ / "d0.csv").string() + "'")),
            "test.yaml: dataset.descriptors: a team of dataset.trajectories gives each robot's own file as "
            "dataset.trajectories[i].descriptors");
  const std::string missing = ErrorOf(Team("files", "d0.csv", "gone.npy"));
  EXPECT_EQ(missing.rfind("test.yaml: dataset.trajectories[1].descriptors: file not found", 0), 0u) << missing;
  // A scenario still renders its descriptors along the drives it plans.
  const std::string scenario = ErrorOf("dataset: {source: files, descriptors: '" + (dir_ / "d0.csv").string() +
                                       "', scenario: {kind: staggered, offset: 5s}}\nrobots: [2]\n");
  EXPECT_EQ(scenario.rfind("test.yaml: dataset.source: dataset.scenario staggered renders its descriptors", 0), 0u)
      << scenario;
}

}  // namespace
}  // namespace dvpr
