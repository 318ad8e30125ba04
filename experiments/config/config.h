#pragma once
// The experiment config (docs/design.md section 7) as typed structs. This is the one place YAML
// enters: LoadConfig() reads a file, applies `--set` overrides to the YAML tree, validates every
// key and returns an ExperimentConfig; nothing below experiments/ sees YAML or strings.
//
// Rules the parser enforces (each violation throws ConfigError, one line naming the key path):
// - unknown keys are rejected, listing the expected ones;
// - durations, data rates and sizes need a unit ("10Mbps", "2ms", "25kB"); the only byte counts
//   that may be plain integers are verification.request_bytes and network.mtu (DESIGN shows
//   `request_bytes: 25000` and "MTU 1500"), read as bytes;
// - relative file paths resolve against the config file's folder first, then the current
//   directory, then the dvpr source tree (so the shipped configs can say data/kitti/...);
//   the resolved, absolute path is what the config holds and what EmitConfig writes;
// - every numeric key has a valid range (docs/config.md lists them; the constants live with the
//   params structs: NetworkModelParams::kMaxLatency, ServiceParams::kMaxFixed, ...); a value
//   outside it, or too large to parse, is "<key>: must be in [min, max], got <value>";
// - a key given twice in one map, and a second YAML document, are errors naming their line;
// - robots >= 2, runs >= 1, dim >= 1, probabilities in [0, 1].
// Checks that need the data (dim larger than the descriptors, frame counts) happen when the data
// is loaded (experiments/protocols/inputs.h) and name the same key paths.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "agents/agent_params.h"
#include "agents/placement/failure_detector.h"
#include "experiments/config/talk_schedule.h"
#include "experiments/domain/data/robot_trajectory.h"
#include "experiments/domain/data/synthetic.h"
#include "experiments/domain/data/synthetic_bow.h"
#include "experiments/domain/data/team_plan.h"
#include "experiments/domain/evaluation/ground_truth.h"
#include "experiments/domain/strategies/run_centroids.h"
#include "experiments/domain/strategies/strategy_spec.h"
#include "net_models/core/units.h"
#include "net_models/helper/link_factory.h"
#include "sim/sim_time.h"

namespace dvpr {

// A config error: what() is one line "<file>: <key.path>: <problem>".
class ConfigError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

enum class DatasetSource { kSynthetic, kFiles };
enum class TrainingSource { kSyntheticDiverse, kSyntheticDeploymentLike, kFiles, kDeployment };

// A section of the config holds the lower layers' own parameter structs (ServiceParams,
// LossParams, ...), read key by key and validated by their own Validate(). Where one YAML value
// is a field of several of them, the reader writes it to each: `seed` is also
// training.run_centroids.seed, dataset.dim also dataset.synthetic.dim, and
// evaluation.suppression_frames also agent.suppression_frames.

struct DatasetConfig {
  // The valid range of fps (docs/config.md). A frame index is an int, so the last frame is at
  // most (2^31 - 1) / kMinFps s = 2.1e18 ns: a run's times stay far inside int64 nanoseconds.
  static constexpr double kMinFps = 1.0;
  static constexpr double kMaxFps = 1e6;

  DatasetSource source = DatasetSource::kSynthetic;
  std::filesystem::path poses;                     // KITTI pose file (absolute after loading)
  std::optional<std::filesystem::path> descriptors;  // required when source = files
  int bin_width = 4096;          // values per frame in a raw float32 .bin file (NetVLAD dumps)
  int dim = 128;                 // the first `dim` descriptor columns are used
  double fps = 10.0;
  std::optional<int> frames;     // empty = all frames; else only the first `frames`
  SyntheticParams synthetic;     // the YAML keys are the field names; dim is dataset.dim
  // Bag-of-words vectors (docs/bow.md), read only when a bow_ strategy runs: the user's file
  // (sparse text, one frame per line of word:weight pairs), or else the synthetic model (set to
  // its defaults by the reader when a bow_ strategy is configured and neither key is given).
  std::optional<std::filesystem::path> bow;
  std::optional<SyntheticBowParams> synthetic_bow;
  // A planned team (experiments/domain/data/team_plan.h): a scenario on the poses other than split, or
  // one pose file per robot (dataset.trajectories; dataset.poses is then not read). A scenario
  // needs the synthetic source; trajectories take it too, or source files with every robot's own
  // descriptor file (dataset.trajectories[i].descriptors). A sweep over robots runs teams of the
  // plan's first n robots (n at most the trajectories' count); strategies without bag-of-words or
  // re-clustering (checked when the config is read).
  ScenarioSpec scenario;
  std::vector<TrajectorySource> trajectories;
  bool Planned() const { return !trajectories.empty() || scenario.kind != ScenarioKind::kSplit; }
  bool operator==(const DatasetConfig&) const = default;
};

struct TrainingConfig {
  TrainingSource source = TrainingSource::kSyntheticDiverse;
  std::optional<std::filesystem::path> descriptors;  // required when source = files
  // Keys centroids (the pattern, absolute; every expansion checked to exist at load time; when
  // set, k-means is skipped) and clusters_per_robot; seed is the config's seed.
  RunCentroidParams run_centroids;
  SyntheticTrainingParams synthetic;
  bool operator==(const TrainingConfig&) const = default;
};

struct SweepConfig {
  std::vector<int> robots{2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20};
  int runs = 10;
  std::vector<std::string> protocols{"paper", "sim"};
  // Parsed when the config is loaded: an unknown or malformed name is a ConfigError.
  std::vector<StrategySpec> strategies{ParseStrategy("decentralized"), ParseStrategy("broadcast")};
  bool operator==(const SweepConfig&) const = default;
};

// One entry of network.routing: the kind, and link_state's beacon periods.
struct NextHopEntry {
  NextHopKind kind = NextHopKind::kDirect;
  LinkStateParams link_state;
  bool operator==(const NextHopEntry&) const = default;
};

struct NetworkConfig;

// The propagations a variant of `model` is run over, one variant each: the radio's, wifi's, or
// the full mesh (every other medium). The one place that decides which media have a propagation.
const std::vector<PropagationParams>& PropagationsOf(const NetworkConfig& network, LinkModelKind model);

// The `network:` section. model, bandwidth, latency, queue_packets and mtu may each be a list;
// the sweep runs their cross product (ExpandNetworks, network_variants.h), each variant a
// NetworkModelParams with this loss and these links.
struct NetworkConfig {
  std::vector<LinkModelKind> model{NetworkModelParams{}.model};
  std::vector<DataRate> bandwidth{NetworkModelParams{}.bandwidth};
  std::vector<SimTime> latency{NetworkModelParams{}.latency};
  std::vector<int> queue_packets{NetworkModelParams{}.queue_packets};
  std::vector<Bytes> mtu{NetworkModelParams{}.wire.mtu};
  LossParams loss;
  std::vector<LinkOverrideParams> links;  // src != dst, each in a team of the sweep at run time
  // Who hears whom on the media that have a propagation (PropagationsOf below), one variant per
  // entry. model radio: network.radio's entries (a `range` list gives one entry per range; a
  // radio section without model radio or wifi over it is refused when the config is read).
  // model wifi: network.wifi.propagation full_mesh (the default: one entry, every robot hears
  // every other) or radio (the radio's entries). Every config reads and writes back in these keys:
  // wifi's entries are the full mesh or the radio's.
  std::vector<PropagationParams> radio{PropagationParams::Radio()};
  std::vector<PropagationParams> wifi_propagation{PropagationParams{}};
  // model wifi: network.wifi's rate (required) and basic_rate.
  WifiParams wifi;
  // network.routing: model radio runs one variant per entry (a list sweeps routings); the other
  // models reach every robot in one hop and route direct (a routing for them is refused).
  std::vector<NextHopEntry> routing{NextHopEntry{}};
  DisconnectedParams disconnected;             // network.disconnected, for every variant (radio only)
  // network.schedule (talk_schedule.h): the file, and its windows by robot; every variant, every
  // model. A window of a robot outside a team applies to the teams that have that robot.
  std::optional<std::filesystem::path> schedule;
  std::vector<ScheduledWindow> windows;
  bool operator==(const NetworkConfig&) const = default;
};

// A robot taken offline at a time (sim). Applies to teams that have that robot.
struct Dropout {
  static constexpr SimTime kMaxAt = SimTime::Millis(100000LL * 3600 * 1000);  // 100000 h

  int robot = 0;
  SimTime at;
  bool operator==(const Dropout&) const = default;
};

struct OutputsConfig {
  bool figures = true;
  bool queries = false;
  bool messages = false;
  bool lcm_log = false;
  // connectivity.csv (issue 33): who reaches whom at every frame period of each simulated run on
  // a radio variant, and its summary in summary.json. Only with a variant of model radio: the
  // other models place no robot, so there is no range to be in.
  bool connectivity = false;
  std::optional<int> pr_robots;  // n of figure 2 (PR curves); empty = 10 if swept, else the largest
  bool operator==(const OutputsConfig&) const = default;
};

// Virtual time 0 of a simulated run as a message timestamp (utime, microseconds since the Unix
// epoch): 2011-10-03T12:00:00Z, the day KITTI 00 was recorded. A fixed instant, not the wall
// clock, so a config gives the same event log every time.
inline constexpr std::int64_t kDefaultStartUtime = 1317643200000000;

struct ExperimentConfig {
  std::string name = "experiment";
  std::uint64_t seed = 1;
  std::int64_t start_utime = kDefaultStartUtime;  // YAML: start_time (utc_instant.h)
  DatasetConfig dataset;
  TrainingConfig training;
  SweepConfig sweep;               // YAML: top-level robots, runs, protocols, strategies
  GroundTruthParams evaluation;    // YAML: evaluation.{gt_radius_m, suppression_frames}
  NetworkConfig network;
  AgentParams agent;               // YAML: sections service and verification
  std::vector<Dropout> dropout;
  OutputsConfig outputs;
  FailoverParams failover;         // YAML: section failover (docs/failover.md)
  bool operator==(const ExperimentConfig&) const = default;
};

// Protocol names the config accepts (strategy names: ParseStrategy).
const std::vector<std::string>& KnownProtocols();

// One `--set key.path=value` override; value is parsed as YAML (scalar, [list] or {map}).
struct ConfigOverride {
  std::string path;   // dotted; numeric segments index lists (dropout.0.at)
  std::string value;
};
// Parses "key.path=value"; throws ConfigError on a malformed argument.
ConfigOverride ParseOverride(const std::string& arg);

// Whether the files a config names must be there when it is read: kNamesOnly resolves them (to the
// first place they are found, else against the config's folder) without a word, for a reader that
// needs only some of them and checks those itself (`dvpr replay` reads the poses, never the
// descriptors or the BoW file of a result folder).
enum class ConfigFiles { kMustExist, kNamesOnly };

// Reads, overrides, validates. Throws ConfigError (bad content) naming the file and key path.
ExperimentConfig LoadConfig(const std::filesystem::path& file,
                            const std::vector<ConfigOverride>& overrides = {},
                            ConfigFiles files = ConfigFiles::kMustExist);
// Same from YAML text; relative paths resolve against `base_dir`, then cwd, then the source tree.
ExperimentConfig ParseConfig(const std::string& yaml_text, const std::filesystem::path& base_dir,
                             const std::vector<ConfigOverride>& overrides = {},
                             const std::string& origin = "<config>", ConfigFiles files = ConfigFiles::kMustExist);

// The fully resolved config as YAML: every key, absolute paths, canonical units. Parsing the
// result gives an equal ExperimentConfig.
std::string EmitConfig(const ExperimentConfig& config);

// Names used in YAML and in result files (the network's and loss's enums have theirs in
// net_models: ToString(LinkModelKind), ToString(LossModelKind)).
std::string_view ToString(DatasetSource source);
std::string_view ToString(TrainingSource source);

}  // namespace dvpr
