#pragma once
// The experiment config (DESIGN.md section 7) as typed structs. This is the one place YAML enters:
// LoadConfig() reads a file, applies `--set` overrides to the YAML tree, validates every key and
// returns an ExperimentConfig; nothing below experiments/ sees YAML or strings.
//
// Rules the parser enforces (each violation throws ConfigError, one line naming the key path):
// - unknown keys are rejected, listing the expected ones;
// - durations, data rates and sizes need a unit ("10Mbps", "2ms", "25kB"); the only byte counts
//   that may be plain integers are verification.request_bytes and network.mtu (DESIGN shows
//   `request_bytes: 25000` and "MTU 1500"), read as bytes;
// - relative file paths resolve against the config file's folder first, then the current
//   directory, then the dvpr source tree (so the shipped configs can say data/kitti/...);
//   the resolved, absolute path is what the config holds and what EmitConfig writes;
// - robots >= 2, runs >= 1, dim >= 1, probabilities in [0, 1].
// Checks that need the data (dim larger than the descriptors, frame counts) happen when the data
// is loaded (experiments/protocols/inputs.h) and name the same key paths.
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "experiments/data/synthetic.h"
#include "experiments/strategies/strategy_spec.h"
#include "net_models/units.h"
#include "sim/sim_time.h"

namespace dvpr {

// A config error: what() is one line "<file>: <key.path>: <problem>".
class ConfigError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Knobs of the synthetic appearance model (experiments/data/synthetic.h, SyntheticParams; the YAML keys
// are the field names, defaults are SyntheticParams' defaults). dim comes from dataset.dim.
struct SyntheticDeploymentKnobs {  // dataset.synthetic
  int place_features = SyntheticParams{}.place_features;
  double length_scale_min_m = SyntheticParams{}.length_scale_min_m;
  double length_scale_max_m = SyntheticParams{}.length_scale_max_m;
  double heading_scale = SyntheticParams{}.heading_scale;
  double heading_fraction = SyntheticParams{}.heading_fraction;
  double variance_decay = SyntheticParams{}.variance_decay;
  double noise = SyntheticParams{}.noise;
  double appearance_change = SyntheticParams{}.appearance_change;
  double appearance_time_scale_frames = SyntheticParams{}.appearance_time_scale_frames;
  double environment_offset = SyntheticParams{}.environment_offset;
  bool operator==(const SyntheticDeploymentKnobs&) const = default;
};
struct SyntheticTrainingKnobs {    // training.synthetic
  int samples = 20000;             // training descriptors generated
  int environments = SyntheticParams{}.environments;  // synthetic_diverse: environments mixed
  double training_area_m = SyntheticParams{}.training_area_m;  // side of the square places are drawn from
  bool operator==(const SyntheticTrainingKnobs&) const = default;
};

enum class DatasetSource { kSynthetic, kFiles };
enum class TrainingSource { kSyntheticDiverse, kSyntheticDeploymentLike, kFiles, kDeployment };

struct DatasetConfig {
  DatasetSource source = DatasetSource::kSynthetic;
  std::filesystem::path poses;                     // KITTI pose file (absolute after loading)
  std::optional<std::filesystem::path> descriptors;  // required when source = files
  int bin_width = 4096;          // values per frame in a raw float32 .bin file (NetVLAD dumps)
  int dim = 128;                 // the first `dim` descriptor columns are used
  double fps = 10.0;
  std::optional<int> frames;     // empty = all frames; else only the first `frames`
  SyntheticDeploymentKnobs synthetic;
  bool operator==(const DatasetConfig&) const = default;
};

struct TrainingConfig {
  TrainingSource source = TrainingSource::kSyntheticDiverse;
  std::optional<std::filesystem::path> descriptors;  // required when source = files
  // Centroid files, {robots} and {run} replaced per run; when set, k-means is skipped.
  // Held as a pattern (absolute), every expansion checked to exist at load time.
  std::optional<std::string> centroids;
  int clusters_per_robot = 1;
  SyntheticTrainingKnobs synthetic;
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

struct EvaluationConfig {
  double gt_radius_m = 5.0;
  int suppression_frames = 250;
  bool operator==(const EvaluationConfig&) const = default;
};

enum class NetworkModel { kIdeal, kPointToPoint, kSharedMedium };
enum class LossModel { kNone, kBernoulli, kGilbertElliott };

struct LossConfig {
  LossModel model = LossModel::kNone;
  double p = 0.0;                  // bernoulli: drop probability per packet
  double p_good_to_bad = 0.0;      // gilbert_elliott: state transition probabilities per packet
  double p_bad_to_good = 1.0;
  double loss_good = 0.0;          // gilbert_elliott: drop probability in each state
  double loss_bad = 1.0;
  bool operator==(const LossConfig&) const = default;
};

// A directed link whose parameters differ from the defaults (network.links).
struct LinkOverride {
  int src = 0;
  int dst = 0;
  std::optional<DataRate> bandwidth;
  std::optional<SimTime> latency;
  std::optional<LossConfig> loss;
  bool operator==(const LinkOverride&) const = default;
};

// One network the sim protocol runs on: every parameter a single value.
struct NetworkSettings {
  NetworkModel model = NetworkModel::kPointToPoint;
  DataRate bandwidth = DataRate::Mbps(10);
  SimTime latency = SimTime::Millis(2);
  int queue_packets = 100;
  Bytes mtu = Bytes(1500);
  LossConfig loss;
  std::vector<LinkOverride> links;
  bool operator==(const NetworkSettings&) const = default;
};

// The `network:` section. model, bandwidth, latency, queue_packets and mtu may each be a list;
// the sweep runs their cross product (ExpandNetworks in sweep.h).
struct NetworkConfig {
  std::vector<NetworkModel> model{NetworkModel::kPointToPoint};
  std::vector<DataRate> bandwidth{DataRate::Mbps(10)};
  std::vector<SimTime> latency{SimTime::Millis(2)};
  std::vector<int> queue_packets{100};
  std::vector<Bytes> mtu{Bytes(1500)};
  LossConfig loss;
  std::vector<LinkOverride> links;
  bool operator==(const NetworkConfig&) const = default;
};

struct VerificationConfig {
  Bytes request_bytes = Bytes(25000);  // geometric-verification request payload
  double max_distance = 0.6;           // a match closer than this triggers verification
  bool operator==(const VerificationConfig&) const = default;
};

struct ServiceConfig {
  SimTime fixed = SimTime::Micros(50);
  SimTime per_comparison = SimTime::Nanos(20);
  bool operator==(const ServiceConfig&) const = default;
};

// A robot taken offline at a time (sim). Applies to teams that have that robot.
struct Dropout {
  int robot = 0;
  SimTime at;
  bool operator==(const Dropout&) const = default;
};

struct OutputsConfig {
  bool figures = true;
  bool queries = false;
  bool messages = false;
  bool lcm_log = false;
  std::optional<int> pr_robots;  // n of figure 2 (PR curves); empty = 10 if swept, else the largest
  bool operator==(const OutputsConfig&) const = default;
};

struct ExperimentConfig {
  std::string name = "experiment";
  std::uint64_t seed = 1;
  DatasetConfig dataset;
  TrainingConfig training;
  SweepConfig sweep;               // YAML: top-level robots, runs, protocols, strategies
  EvaluationConfig evaluation;
  NetworkConfig network;
  VerificationConfig verification;
  ServiceConfig service;
  std::vector<Dropout> dropout;
  OutputsConfig outputs;
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

// Reads, overrides, validates. Throws ConfigError (bad content) naming the file and key path.
ExperimentConfig LoadConfig(const std::filesystem::path& file,
                            const std::vector<ConfigOverride>& overrides = {});
// Same from YAML text; relative paths resolve against `base_dir`, then cwd, then the source tree.
ExperimentConfig ParseConfig(const std::string& yaml_text, const std::filesystem::path& base_dir,
                             const std::vector<ConfigOverride>& overrides = {},
                             const std::string& origin = "<config>");

// The fully resolved config as YAML: every key, absolute paths, canonical units. Parsing the
// result gives an equal ExperimentConfig.
std::string EmitConfig(const ExperimentConfig& config);

// Names used in YAML and in result files.
std::string ToString(NetworkModel model);
std::string ToString(LossModel model);
std::string ToString(DatasetSource source);
std::string ToString(TrainingSource source);
// A duration in the largest unit that keeps it whole ("2ms", "50us", "20ns").
std::string FormatDuration(SimTime t);

// The centroid file of one run: pattern with {robots} and {run} replaced.
std::filesystem::path CentroidPath(const std::string& pattern, int robots, int run);

}  // namespace dvpr
