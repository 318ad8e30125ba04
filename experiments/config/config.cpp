// YAML -> ExperimentConfig. One function per section; each reads only the keys it lists in
// ExpectMap, so a key the parser does not know is always reported.
#include "experiments/config/config.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <fstream>
#include <optional>
#include <set>
#include <sstream>

#include <yaml-cpp/yaml.h>

#include "experiments/config/config_reader.h"
#include "experiments/config/utc_instant.h"
#include "experiments/config/yaml_check.h"
#include "experiments/domain/data/text_file.h"
#include "experiments/domain/strategies/strategy_spec.h"

namespace dvpr {

namespace {
// The longest `name`: a folder's name on Linux (NAME_MAX).
constexpr std::size_t kMaxNameBytes = 255;
}  // namespace

const std::vector<PropagationParams>& PropagationsOf(const NetworkConfig& network, LinkModelKind model) {
  static const std::vector<PropagationParams> kFullMesh{PropagationParams{}};
  switch (model) {
    case LinkModelKind::kRadio: return network.radio;
    case LinkModelKind::kWifi: return network.wifi_propagation;
    default: return kFullMesh;
  }
}

using config_detail::Field;
using config_detail::Origin;

namespace {

template <typename Enum, std::size_t N>
Enum ReadEnum(const Field& f, const std::array<std::string_view, N>& names) {
  return static_cast<Enum>(f.Choice(std::vector<std::string>(names.begin(), names.end())));
}

// The valid ranges together keep a query's times representable (the brief of each range is at its
// constant). Worst cases: the last frame at (2^31 - 1) / kMinFps s; a service time of kMaxFixed +
// kMaxPerComparison x 2^31 comparisons; a transmission of at most twice the largest request (IPv4
// fragments at MTU 68 carry 48 data bytes in 70) at kMinBandwidth; a dropout at kMaxAt. The last
// frame plus 16 of each of the others stays below half of int64 nanoseconds, leaving the other half
// to queueing.
constexpr bool WorstCaseTimesFit() {
  const double last_frame = 2147483647.0 / DatasetConfig::kMinFps * 1e9;
  const double service = static_cast<double>(ServiceParams::kMaxFixed.ns()) +
                         static_cast<double>(ServiceParams::kMaxPerComparison.ns()) * 2147483648.0;
  const double transmission = 2.0 * static_cast<double>(VerificationParams::kMaxRequestBytes.value()) * 8 * 1e9 /
                              static_cast<double>(NetworkModelParams::kMinBandwidth.bps());
  const double latency = static_cast<double>(NetworkModelParams::kMaxLatency.ns());
  const double dropout = static_cast<double>(Dropout::kMaxAt.ns());
  return last_frame + 16 * (service + transmission + latency) + dropout < 4.6e18;
}
static_assert(WorstCaseTimesFit(), "the config's ranges must keep a run's times inside int64 nanoseconds");

// Valid UTF-8 without control characters. The emitter writes other bytes differently (invalid
// UTF-8 as U+FFFD), so config.yaml would not name the folder the run wrote (found by fuzz_config).
bool IsPrintableUtf8(std::string_view s) {
  for (std::size_t i = 0; i < s.size();) {
    const auto c = static_cast<unsigned char>(s[i]);
    if (c < 0x20 || c == 0x7f) return false;
    const std::size_t len = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xe ? 3 : (c >> 3) == 0x1e ? 4 : 0;
    if (len == 0 || i + len > s.size()) return false;
    for (std::size_t k = 1; k < len; ++k) {
      if ((static_cast<unsigned char>(s[i + k]) & 0xc0) != 0x80) return false;
    }
    i += len;
  }
  return true;
}

// The one spelling of each source, indexed by the enum's value (ToString and the reader).
constexpr std::array<std::string_view, 2> kDatasetSources{"synthetic", "files"};
constexpr std::array<std::string_view, 4> kTrainingSources{"synthetic_diverse", "synthetic_deployment_like",
                                                           "files", "deployment"};

// dataset.synthetic: the appearance model's fields under their own names; dim is dataset.dim.
SyntheticParams ReadSyntheticModel(const Field& f, int dim) {
  SyntheticParams p;
  p.dim = dim;
  if (f.present()) {
    f.ExpectMap({"place_features", "length_scale_min_m", "length_scale_max_m", "heading_scale",
                 "heading_fraction", "variance_decay", "noise", "appearance_change",
                 "appearance_time_scale_frames", "environment_offset"});
    if (auto c = f.Child("place_features"); c.present()) {
      p.place_features = static_cast<int>(c.Int(1, 1 << 20));
    }
    const std::pair<const char*, double*> numbers[] = {
        {"length_scale_min_m", &p.length_scale_min_m}, {"length_scale_max_m", &p.length_scale_max_m},
        {"heading_scale", &p.heading_scale}, {"heading_fraction", &p.heading_fraction},
        {"variance_decay", &p.variance_decay}, {"noise", &p.noise},
        {"appearance_change", &p.appearance_change},
        {"appearance_time_scale_frames", &p.appearance_time_scale_frames},
        {"environment_offset", &p.environment_offset}};
    for (const auto& [key, value] : numbers) {
      if (auto c = f.Child(key); c.present()) *value = c.Double();
    }
  }
  f.Validate(p);
  return p;
}

// training.synthetic: the training sets' fields under their own names.
SyntheticTrainingParams ReadSyntheticTraining(const Field& f) {
  SyntheticTrainingParams t;
  if (!f.present()) return t;
  f.ExpectMap({"samples", "environments", "training_area_m"});
  if (auto c = f.Child("samples"); c.present()) t.samples = static_cast<int>(c.Int(1, 10000000));
  if (auto c = f.Child("environments"); c.present()) {
    t.environments = static_cast<int>(c.Int(1, 100000));
  }
  if (auto c = f.Child("training_area_m"); c.present()) t.training_area_m = c.Double();
  f.Validate(t);
  return t;
}

// dataset.synthetic_bow: the BoW model's fields under their own names (docs/bow.md).
SyntheticBowParams ReadSyntheticBow(const Field& f) {
  SyntheticBowParams p;
  f.ExpectMap({"features", "vocabulary", "landmark_density", "range_m", "field_of_view_deg", "common_words",
               "common_share", "view_sector_deg"});
  if (auto c = f.Child("features"); c.present()) p.features = static_cast<int>(c.Int(1, 100000));
  if (auto c = f.Child("vocabulary"); c.present()) p.vocabulary = static_cast<int>(c.Int(2, 10000000));
  // Its upper end, vocabulary - 1, is Validate's to check (the vocabulary may come later in the map).
  if (auto c = f.Child("common_words"); c.present()) p.common_words = static_cast<int>(c.Int(0, 10000000));
  const std::pair<const char*, double*> numbers[] = {{"landmark_density", &p.landmark_density},
                                                     {"range_m", &p.range_m},
                                                     {"field_of_view_deg", &p.field_of_view_deg},
                                                     {"common_share", &p.common_share},
                                                     {"view_sector_deg", &p.view_sector_deg}};
  for (const auto& [key, value] : numbers) {
    if (auto c = f.Child(key); c.present()) *value = c.Double();
  }
  f.Validate(p);
  return p;
}

ScenarioSpec ReadScenario(const Field& f);
TrajectorySource ReadTrajectorySource(const Field& f);

DatasetConfig ReadDataset(const Field& f) {
  DatasetConfig d;
  f.ExpectMap({"source", "poses", "descriptors", "bin_width", "dim", "fps", "frames", "synthetic", "bow",
               "synthetic_bow", "scenario", "trajectories"});
  if (auto c = f.Child("source"); c.present()) d.source = ReadEnum<DatasetSource>(c, kDatasetSources);
  const Field poses = f.Child("poses");
  // A team of dataset.trajectories reads no dataset.poses; the shipped KITTI 00 is the default.
  if (poses.present()) {
    d.poses = poses.ExistingFile();
  } else if (!f.Child("trajectories").present()) {
    d.poses = Field(f.origin(), YAML::Node("data/kitti/00_poses.txt"), poses.path()).ExistingFile();
  }
  const Field desc = f.Child("descriptors");
  if (desc.present()) d.descriptors = desc.ExistingFile();
  if (desc.present() && f.Child("trajectories").present()) {
    desc.Fail("a team of dataset.trajectories gives each robot's own file as dataset.trajectories[i].descriptors");
  }
  if (d.source == DatasetSource::kFiles && !d.descriptors && !f.Child("trajectories").present()) {
    desc.Fail("required when dataset.source is files (an .npy, .bin or .csv file)");
  }
  if (auto c = f.Child("bin_width"); c.present()) d.bin_width = static_cast<int>(c.Int(1, 1 << 20));
  if (auto c = f.Child("dim"); c.present()) d.dim = static_cast<int>(c.Int(1, 1 << 20));
  if (auto c = f.Child("fps"); c.present()) d.fps = c.Double(DatasetConfig::kMinFps, DatasetConfig::kMaxFps);
  if (auto c = f.Child("frames"); c.present()) {
    if (!(c.node().IsScalar() && c.node().Scalar() == "all")) {
      d.frames = static_cast<int>(c.Int(1, 1 << 30));
    }
  }
  d.synthetic = ReadSyntheticModel(f.Child("synthetic"), d.dim);
  if (const Field bow = f.Child("bow"); bow.present()) d.bow = bow.ExistingFile();
  if (const Field model = f.Child("synthetic_bow"); model.present()) d.synthetic_bow = ReadSyntheticBow(model);
  if (const Field s = f.Child("scenario"); s.present()) d.scenario = ReadScenario(s);
  if (const Field t = f.Child("trajectories"); t.present()) {
    for (const Field& item : t.Items()) d.trajectories.push_back(ReadTrajectorySource(item));
    if (d.scenario.kind != ScenarioKind::kSplit) {
      f.Child("scenario").Fail("a team of dataset.trajectories drives its own poses; leave the scenario split");
    }
  }
  return d;
}

// dataset.scenario: a kind, or a map {kind, offset, length, seed} (experiments/domain/data/team_plan.h).
ScenarioSpec ReadScenario(const Field& f) {
  ScenarioSpec s;
  if (f.node().IsScalar()) {
    s.kind = f.Named(ParseScenarioKind);
  } else {
    f.ExpectMap({"kind", "offset", "length", "seed"});
    const Field kind = f.Child("kind");
    if (!kind.present()) kind.Fail("required: split, staggered, reverse or random_routes");
    s.kind = kind.Named(ParseScenarioKind);
    if (auto c = f.Child("offset"); c.present()) {
      s.offset_s = c.Duration(SimTime::Zero(), SimTime::Seconds(360000000)).ToSeconds();
    }
    if (auto c = f.Child("length"); c.present()) s.length = static_cast<int>(c.Int(2, 1 << 30));
    if (auto c = f.Child("seed"); c.present()) {
      s.seed = static_cast<std::uint64_t>(c.Int(0, std::numeric_limits<long long>::max()));
    }
  }
  f.Validate(s);
  return s;
}

// One entry of dataset.trajectories: {poses, format, start, fps, times, frame}.
TrajectorySource ReadTrajectorySource(const Field& f) {
  f.ExpectMap({"poses", "format", "start", "fps", "times", "frame", "descriptors"});
  TrajectorySource s;
  const Field poses = f.Child("poses");
  if (!poses.present()) poses.Fail("required: the robot's pose file");
  s.poses = poses.ExistingFile();
  const Field format = f.Child("format");
  if (!format.present()) format.Fail("required: kitti, tum or csv");
  s.format = ReadEnum<TrajectoryFormat>(format, kTrajectoryFormatNames);
  if (auto c = f.Child("start"); c.present()) {
    s.start_s = c.Duration(SimTime::Zero(), SimTime::Seconds(360000000)).ToSeconds();
  }
  if (auto c = f.Child("fps"); c.present()) s.fps = c.Double();  // TrajectorySource::Validate checks it
  if (auto c = f.Child("times"); c.present()) s.times = c.ExistingFile();
  if (auto c = f.Child("frame"); c.present()) s.frame = c.String();
  if (auto c = f.Child("descriptors"); c.present()) s.descriptors = c.ExistingFile();
  f.Validate(s);
  return s;
}

// Makes a centroid file pattern absolute and checks every file the sweep will read. A file that is
// there but is not a regular file (a FIFO, ...) is named as what it is (text_file::NotARegularFile).
std::string ResolveCentroids(const Field& f, const SweepConfig& sweep) {
  const std::string pattern = f.String();
  for (const auto& dir : config_detail::SearchDirs(f.origin())) {
    const std::filesystem::path candidate =
        std::filesystem::path(pattern).is_absolute() ? std::filesystem::path(pattern) : dir / pattern;
    if (text_file::NotARegularFile(ExpandCentroidPattern(candidate.string(), sweep.robots[0], 0)) ==
        text_file::kNoSuchFile) {
      continue;
    }
    for (int n : sweep.robots) {
      for (int r = 0; r < sweep.runs; ++r) {
        const auto file = ExpandCentroidPattern(candidate.string(), n, r);
        const std::string why = text_file::NotARegularFile(file);
        if (!why.empty()) {
          f.Fail((why == text_file::kNoSuchFile ? "file not found: '" + file.string() + "'"
                                                : "'" + file.string() + "' " + why) +
                 " (robots " + std::to_string(n) + ", run " + std::to_string(r) + ")");
        }
      }
    }
    return std::filesystem::absolute(candidate).lexically_normal().string();
  }
  f.Fail("file not found: '" + ExpandCentroidPattern(pattern, sweep.robots[0], 0).string() +
         "' (the pattern for robots " + std::to_string(sweep.robots[0]) + ", run 0)");
}

TrainingConfig ReadTraining(const Field& f, const SweepConfig& sweep, std::uint64_t seed) {
  TrainingConfig t;
  t.run_centroids.seed = seed;
  if (!f.present()) return t;
  f.ExpectMap({"source", "descriptors", "centroids", "clusters_per_robot", "synthetic"});
  if (auto c = f.Child("source"); c.present()) {
    t.source = ReadEnum<TrainingSource>(c, kTrainingSources);
  }
  const Field desc = f.Child("descriptors");
  if (desc.present()) t.descriptors = desc.ExistingFile();
  if (t.source == TrainingSource::kFiles && !t.descriptors) {
    desc.Fail("required when training.source is files (an .npy, .bin or .csv file)");
  }
  if (auto c = f.Child("centroids"); c.present()) {
    t.run_centroids.centroids_pattern = ResolveCentroids(c, sweep);
  }
  if (auto c = f.Child("clusters_per_robot"); c.present()) {
    t.run_centroids.clusters_per_robot = static_cast<int>(c.Int(1, 1000));
  }
  t.synthetic = ReadSyntheticTraining(f.Child("synthetic"));
  return t;
}

std::vector<int> ReadRobots(const Field& f) {
  std::vector<int> robots;
  if (f.node().IsMap()) {
    f.ExpectMap({"from", "to"});
    const int from = static_cast<int>(f.Child("from").Int(2, 100000));
    const int to = static_cast<int>(f.Child("to").Int(2, 100000));
    if (to < from) f.Child("to").Fail("must be at least robots.from (" + std::to_string(from) + ")");
    for (int n = from; n <= to; ++n) robots.push_back(n);
    return robots;
  }
  for (const Field& item : f.Items()) {
    const int n = static_cast<int>(item.Int(2, 100000));
    if (std::find(robots.begin(), robots.end(), n) != robots.end()) item.Fail("listed twice");
    robots.push_back(n);
  }
  return robots;
}

std::vector<std::string> ReadNames(const Field& f, const std::vector<std::string>& known) {
  std::vector<std::string> names;
  for (const Field& item : f.Items()) {
    const std::string name = known[item.Choice(known)];
    if (std::find(names.begin(), names.end(), name) != names.end()) item.Fail("listed twice");
    names.push_back(name);
  }
  return names;
}

// Every name parsed into its spec now, so a typo fails before any run.
std::vector<StrategySpec> ReadStrategies(const Field& f) {
  std::vector<StrategySpec> specs;
  for (const Field& item : f.Items()) {
    StrategySpec spec;
    try {
      spec = ParseStrategy(item.String());
    } catch (const std::invalid_argument& e) {
      item.Fail(e.what());
    }
    for (const StrategySpec& s : specs) {
      if (s.name == spec.name) item.Fail("listed twice");
    }
    specs.push_back(std::move(spec));
  }
  return specs;
}

SweepConfig ReadSweep(const Field& root) {
  SweepConfig s;
  if (auto c = root.Child("robots"); c.present()) s.robots = ReadRobots(c);
  if (auto c = root.Child("runs"); c.present()) s.runs = static_cast<int>(c.Int(1, 100000));
  if (auto c = root.Child("protocols"); c.present()) s.protocols = ReadNames(c, KnownProtocols());
  if (auto c = root.Child("strategies"); c.present()) s.strategies = ReadStrategies(c);
  return s;
}

GroundTruthParams ReadEvaluation(const Field& f) {
  GroundTruthParams e;
  if (!f.present()) return e;
  f.ExpectMap({"gt_radius_m", "suppression_frames"});
  if (auto c = f.Child("gt_radius_m"); c.present()) {
    // [1 mm, 1e9 m]: poses lie within 1e9 m (the pose loader's range), so a larger radius says
    // nothing more, and the online metrics' grid cells (position / radius) stay far inside int64.
    e.radius_m = c.Double(1e-3, 1e9);
  }
  if (auto c = f.Child("suppression_frames"); c.present()) {
    e.suppression_frames = static_cast<int>(c.Int(0, 1 << 30));
  }
  f.Validate(e);
  return e;
}

}  // namespace

// Declared in config_sections.cpp (network, verification, service, dropout, outputs).
namespace config_detail {
NetworkConfig ReadNetwork(const Field& f, const SweepConfig& sweep);
VerificationParams ReadVerification(const Field& f);
ServiceParams ReadService(const Field& f);
std::vector<Dropout> ReadDropout(const Field& f, const SweepConfig& sweep);
OutputsConfig ReadOutputs(const Field& f, const SweepConfig& sweep, const NetworkConfig& network);
FailoverParams ReadFailover(const Field& f, const SweepConfig& sweep);
}  // namespace config_detail

namespace {

std::int64_t ReadStartTime(const Field& f) {
  const std::string s = f.String();
  if (const auto utime = ParseUtcInstant(s)) return *utime;
  f.Fail("expected a UTC instant YYYY-MM-DDTHH:MM:SS[.ffffff]Z in [" + FormatUtcInstant(kMinUtcInstant) + ", " +
         FormatUtcInstant(kMaxUtcInstant) + "], got '" + s + "'");
}

// dataset.trajectories' own descriptor files: with dataset.source files every entry names one,
// with synthetic none does (its descriptors are rendered); the first entry that breaks the rule is
// named, and with it an entry that keeps it.
void CheckTrajectoryDescriptors(const Field& dataset, const DatasetConfig& d) {
  if (d.trajectories.empty()) return;
  const std::vector<Field> entries = dataset.Child("trajectories").Items();
  const auto entry = [](std::size_t r) { return "dataset.trajectories[" + std::to_string(r) + "]"; };
  const bool files = d.source == DatasetSource::kFiles;
  std::optional<std::size_t> with;
  for (std::size_t r = 0; r < d.trajectories.size() && !with; ++r) {
    if (d.trajectories[r].descriptors) with = r;
  }
  for (std::size_t r = 0; r < d.trajectories.size(); ++r) {
    if (files && !d.trajectories[r].descriptors) {
      entries[r].Child("descriptors").Fail(
          "required when dataset.source is files: one descriptor file per robot (an .npy, .bin or .csv file, one "
          "row per pose)" + (with ? "; " + entry(*with) + " names one, this entry none" : std::string()));
    }
  }
  if (!files && with) {
    entries[*with].Child("descriptors").Fail(
        "a descriptor file of the robot's own needs dataset.source: files (with synthetic, every robot's "
        "descriptors are rendered by the model)");
  }
}

// What a planned team (dataset.scenario other than split, or dataset.trajectories) can run with
// (docs/config.md, "Team plans"): teams of its first n robots (n at most the trajectories'
// count), descriptors the synthetic model renders along every robot's own poses and times (or the
// trajectories' own files), and strategies that need neither the paper's split nor bag-of-words
// vectors.
void CheckTeamPlan(const Field& root, const ExperimentConfig& c) {
  const DatasetConfig& d = c.dataset;
  if (!d.Planned()) return;
  const std::string plan = d.trajectories.empty() ? "dataset.scenario " + std::string(ToString(d.scenario.kind))
                                                  : "dataset.trajectories";
  const Field dataset = root.Child("dataset");
  if (d.trajectories.empty() && d.source != DatasetSource::kSynthetic) {
    dataset.Child("source").Fail(plan + " renders its descriptors with the synthetic model along every robot's "
                                 "own poses and times: source must be synthetic (a team with descriptor files of "
                                 "its own gives them as dataset.trajectories[i].descriptors)");
  }
  CheckTrajectoryDescriptors(dataset, d);
  if (!d.trajectories.empty() && d.frames) {
    dataset.Child("frames").Fail("dataset.frames cuts dataset.poses, which a team of dataset.trajectories does not read");
  }
  // A sweep over team sizes runs teams of the plan's first n robots: n at most the trajectories'.
  const std::size_t given = d.trajectories.size();
  for (const int n : c.sweep.robots) {
    if (given > 0 && static_cast<std::size_t>(n) > given) {
      root.Child("robots").Fail(std::to_string(n) + " robots, but dataset.trajectories gives " + std::to_string(given) +
                                " (a team of n robots drives the first n trajectories): every count at most " +
                                std::to_string(given));
    }
  }
  for (const StrategySpec& s : c.sweep.strategies) {
    if (s.bag_of_words() || s.reclusters()) {
      root.Child("strategies").Fail(plan + ": strategy " + s.name + " is not available for a planned team "
                                    "(bag-of-words vectors and re-clustering epochs follow the paper's split)");
    }
  }
}

ExperimentConfig ReadExperiment(const Field& root, const std::string& default_name) {
  if (!root.present()) root.Fail("the config is empty");
  root.ExpectMap({"name", "seed", "start_time", "dataset", "training", "robots", "runs", "protocols",
                  "strategies", "evaluation", "network", "verification", "service", "dropout",
                  "outputs", "failover"});
  ExperimentConfig c;
  c.name = default_name;
  if (auto f = root.Child("name"); f.present()) {
    c.name = f.String();
    if (c.name.empty() || c.name.find_first_of("/\\") != std::string::npos || c.name == "." ||
        c.name == ".." || !IsPrintableUtf8(c.name)) {
      f.Fail("expected a non-empty name without slashes, control characters or invalid UTF-8, "
             "not . or .. (it names the output folder)");
    }
    // A folder's name has at most 255 bytes (NAME_MAX): a longer name failed when the output
    // folder was made, in an error line that quoted all of it and named neither `name` nor --out.
    if (c.name.size() > kMaxNameBytes) {
      f.Fail("expected at most " + std::to_string(kMaxNameBytes) + " bytes (it names the output folder), got " +
             std::to_string(c.name.size()));
    }
  }
  if (auto f = root.Child("seed"); f.present()) {
    c.seed = static_cast<std::uint64_t>(f.Int(0, std::numeric_limits<long long>::max()));
  }
  if (auto f = root.Child("start_time"); f.present()) c.start_utime = ReadStartTime(f);
  const Field dataset = root.Child("dataset");
  c.dataset = ReadDataset(dataset.present() ? dataset
                                            : Field(root.origin(), YAML::Node(YAML::NodeType::Map),
                                                    "dataset"));
  c.sweep = ReadSweep(root);
  const bool bow = std::any_of(c.sweep.strategies.begin(), c.sweep.strategies.end(),
                               [](const StrategySpec& s) { return s.bag_of_words(); });
  if (bow && !c.dataset.bow && !c.dataset.synthetic_bow) c.dataset.synthetic_bow = SyntheticBowParams{};
  c.training = ReadTraining(root.Child("training"), c.sweep, c.seed);
  c.evaluation = ReadEvaluation(root.Child("evaluation"));
  c.network = config_detail::ReadNetwork(root.Child("network"), c.sweep);
  c.agent.suppression_frames = c.evaluation.suppression_frames;
  c.agent.verification = config_detail::ReadVerification(root.Child("verification"));
  c.agent.service = config_detail::ReadService(root.Child("service"));
  c.dropout = config_detail::ReadDropout(root.Child("dropout"), c.sweep);
  c.outputs = config_detail::ReadOutputs(root.Child("outputs"), c.sweep, c.network);
  c.failover = config_detail::ReadFailover(root.Child("failover"), c.sweep);
  CheckTeamPlan(root, c);
  return c;
}

bool IsIndex(const std::string& s) {
  return !s.empty() && s.find_first_not_of("0123456789") == std::string::npos;
}

// Walks (and creates) the maps along `path` and sets the last key to `value`.
void ApplyOverride(YAML::Node& root, const ConfigOverride& o, const std::string& origin) {
  YAML::Node value;
  config_detail::CheckOverrideStructure(o.value, origin, o.path);
  try {
    value = YAML::Load(o.value);
  } catch (const YAML::Exception& e) {
    throw ConfigError(origin + ": --set " + o.path + ": value is not valid YAML: " + e.msg);
  }
  if (!root.IsMap()) root = YAML::Node(YAML::NodeType::Map);
  YAML::Node cur = root;
  std::istringstream segments(o.path);
  std::vector<std::string> keys;
  for (std::string s; std::getline(segments, s, '.');) keys.push_back(s);
  for (std::size_t i = 0; i < keys.size(); ++i) {
    const std::string& key = keys[i];
    const bool last = i + 1 == keys.size();
    if (cur.IsSequence() && IsIndex(key)) {
      // Past every list before std::stoul could overflow (a bug's exit status, not a user error's).
      const std::size_t idx = key.size() > 9 ? cur.size() : std::stoul(key);
      if (idx >= cur.size()) {
        throw ConfigError(origin + ": --set " + o.path + ": index " + key + " is past the end");
      }
      if (last) { cur[idx] = value; return; }
      YAML::Node next = cur[idx];
      cur.reset(next);
      continue;
    }
    if (!cur.IsMap()) cur = YAML::Node(YAML::NodeType::Map);  // replaces a scalar in place
    if (last) { cur[key] = value; return; }
    if (!cur[key].IsMap() && !cur[key].IsSequence()) cur[key] = YAML::Node(YAML::NodeType::Map);
    YAML::Node next = cur[key];
    cur.reset(next);
  }
}

}  // namespace

const std::vector<std::string>& KnownProtocols() {
  static const std::vector<std::string> names{"paper", "sim"};
  return names;
}

ConfigOverride ParseOverride(const std::string& arg) {
  const auto eq = arg.find('=');
  if (eq == std::string::npos || eq == 0) {
    throw ConfigError("--set " + arg + ": expected key.path=value");
  }
  ConfigOverride o{arg.substr(0, eq), arg.substr(eq + 1)};
  if (o.path.front() == '.' || o.path.back() == '.' || o.path.find("..") != std::string::npos) {
    throw ConfigError("--set " + arg + ": malformed key path '" + o.path + "'");
  }
  // Keys are names; a list is set whole (dropout[0].robot would be read as an unknown key).
  if (const auto bracket = o.path.find_first_of("[]"); bracket != std::string::npos) {
    const std::string list = o.path.substr(0, o.path.find('['));
    throw ConfigError("--set " + arg + ": a key path names map keys only, not list elements; set the whole list, e.g. --set '" +
                      (list.empty() ? std::string("dropout") : list) + "=[...]'");
  }
  return o;
}

ExperimentConfig ParseConfig(const std::string& yaml_text, const std::filesystem::path& base_dir,
                             const std::vector<ConfigOverride>& overrides,
                             const std::string& origin, ConfigFiles files) {
  config_detail::CheckYamlStructure(yaml_text, origin);
  YAML::Node root;
  try {
    root = YAML::Load(yaml_text);
  } catch (const YAML::Exception& e) {
    throw ConfigError(origin + ": not valid YAML: " + e.what());
  }
  for (const auto& o : overrides) ApplyOverride(root, o, origin);
  const Origin where{origin, base_dir, files};
  const std::string stem = std::filesystem::path(origin).stem().string();
  return ReadExperiment(Field(where, root, ""), stem.empty() || stem[0] == '<' ? "experiment" : stem);
}

ExperimentConfig LoadConfig(const std::filesystem::path& file,
                            const std::vector<ConfigOverride>& overrides, ConfigFiles files) {
  std::error_code ec;
  if (std::filesystem::is_directory(file, ec)) {
    throw ConfigError(file.string() + ": is a directory, expected a YAML config file");
  }
  std::ifstream in(file, std::ios::binary);
  if (!in) throw ConfigError(file.string() + ": cannot read the config file");
  std::ostringstream text;
  text << in.rdbuf();
  const auto base = std::filesystem::absolute(file).parent_path();
  return ParseConfig(text.str(), base, overrides, file.string(), files);
}

std::string_view ToString(DatasetSource s) { return kDatasetSources[static_cast<std::size_t>(s)]; }
std::string_view ToString(TrainingSource s) { return kTrainingSources[static_cast<std::size_t>(s)]; }

}  // namespace dvpr
