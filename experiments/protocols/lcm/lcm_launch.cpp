#include "experiments/protocols/lcm/lcm_launch.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstring>
#include <fstream>
#include <random>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "agents/auth/team_secret.h"
#include "agents/lcm/lcm_transport.h"
#include "experiments/config/option_reader.h"
#include "experiments/domain/data/split.h"
#include "experiments/domain/evaluation/metrics.h"
#include "experiments/domain/strategies/run_centroids.h"
#include "experiments/protocols/inputs.h"
#include "experiments/protocols/lcm/agent_process.h"
#include "experiments/protocols/sim/sim_protocol.h"
#include "experiments/results/protocol_traits.h"
#include "experiments/results/result_folder.h"
#include "experiments/results/result_writers.h"

namespace dvpr {

void LaunchOptions::Validate() const {
  if (config.empty()) throw std::invalid_argument("--config is required");
  if (robots < 2) throw std::invalid_argument("--robots is required (at least 2)");
  if (run < 0) throw std::invalid_argument("--run must be >= 0");
  if (!lcm_url.empty()) CheckLcmUrl(lcm_url);
  CheckSpeedup(speedup);
  CheckWallSeconds("--grace", grace_s, 0, false);
  CheckWallSeconds("--timeout", timeout_s, 0, false);
  CheckHoldBytes(hold_bytes);
}

LaunchOptions ParseLaunchArgs(const std::vector<std::string>& args) {
  LaunchOptions o;
  OptionReader in(args);
  while (in.Next()) {
    const std::string& f = in.flag();
    if (f == "--config") o.config = in.Text();
    else if (f == "--set") o.overrides.push_back(ParseOverride(in.Text()));
    else if (f == "--robots") o.robots = in.Int();
    else if (f == "--run") o.run = in.Int();
    else if (f == "--out") o.out = in.Text();
    else if (f == "--lcm") o.lcm_url = in.Text();
    else if (f == "--speedup") o.speedup = in.Double();
    else if (f == "--grace") o.grace_s = in.Double();
    else if (f == "--timeout") o.timeout_s = in.Double();
    else if (f == "--hold-bytes") o.hold_bytes = in.Int64();
    else in.Unknown();
  }
  o.Validate();
  return o;
}

namespace {

struct Child {
  int robot = 0;
  pid_t pid = -1;
  int status = 0;
  bool exited = false;
  bool killed_at_timeout = false;
};

std::string Describe(const Child& c) {
  if (c.killed_at_timeout) return "killed at the launch timeout";
  if (WIFEXITED(c.status)) return "exit " + std::to_string(WEXITSTATUS(c.status));
  if (WIFSIGNALED(c.status)) return std::string("signal ") + std::to_string(WTERMSIG(c.status));
  return "unknown";
}

// fork/exec of `argv` with stdout and stderr to `log_file`, a new file in the launch's own
// temporary result folder: made exclusively and never through a link (issue 31); a child that
// cannot make it exits 126 without running, which the launch reports as that robot's exit.
pid_t Spawn(const std::vector<std::string>& argv, const std::filesystem::path& log_file) {
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  const std::string log = log_file.string();
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error(std::string("fork failed: ") + std::strerror(errno));
  if (pid == 0) {  // child: only async-signal-safe calls until exec
    const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW, 0644);
    if (fd < 0) _exit(126);
    dup2(fd, STDOUT_FILENO);
    dup2(fd, STDERR_FILENO);
    close(fd);
    execv(args[0], args.data());
    _exit(127);
  }
  return pid;
}

// Waits for every child until `timeout`; SIGKILLs the ones still running then.
void WaitAll(std::vector<Child>& children, std::chrono::steady_clock::duration timeout) {
  const auto end = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    bool running = false;
    for (Child& c : children) {
      if (c.exited) continue;
      if (waitpid(c.pid, &c.status, WNOHANG) == c.pid) c.exited = true;
      else running = true;
    }
    if (!running) return;
    if (std::chrono::steady_clock::now() >= end) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));  // polling a handful of children
  }
  for (Child& c : children) {
    if (c.exited) continue;
    kill(c.pid, SIGKILL);
    waitpid(c.pid, &c.status, 0);
    c.exited = true;
    c.killed_at_timeout = true;
  }
}

// A robot the config drops (`dropout:`) kills its own process (dvpr agent): that is no failure.
bool DroppedOnPurpose(const ExperimentConfig& config, const Child& c) {
  if (c.killed_at_timeout || !WIFSIGNALED(c.status) || WTERMSIG(c.status) != SIGKILL) return false;
  return std::any_of(config.dropout.begin(), config.dropout.end(), [&](const Dropout& d) { return d.robot == c.robot; });
}

// This launch's team nonce (agent_process.h): another launch of the same config on the same URL
// draws another, so the two teams never take each other's heartbeats or messages.
std::uint64_t DrawTeamNonce() {
  std::random_device device;
  std::uint64_t nonce = 0;
  while (nonce == 0) nonce = (std::uint64_t{device()} << 32) ^ device();
  return nonce;
}

std::vector<std::string> AgentArgv(const LaunchOptions& o, std::uint64_t nonce, const std::filesystem::path& secret,
                                   const std::string& strategy, int robot, const std::filesystem::path& log) {
  std::vector<std::string> a{o.binary.string(), "agent", "--config", o.config.string()};
  for (const auto& s : o.overrides) {
    a.push_back("--set");
    a.push_back(s.path + "=" + s.value);
  }
  auto add = [&](const std::string& k, const std::string& v) { a.push_back(k); a.push_back(v); };
  std::ostringstream speedup, grace;
  speedup.precision(17);
  grace.precision(17);
  speedup << o.speedup;
  grace << o.grace_s;
  add("--robot", std::to_string(robot));
  add("--robots", std::to_string(o.robots));
  add("--run", std::to_string(o.run));
  add("--strategy", strategy);
  add("--lcm", o.lcm_url.empty() ? kDefaultLcmUrl : o.lcm_url);
  add("--team-nonce", TeamNonceText(nonce));
  add("--team-secret", secret.string());  // the file's name, never the secret itself
  add("--hold-bytes", std::to_string(o.hold_bytes));
  add("--speedup", speedup.str());
  add("--grace", grace.str());
  add("--out", log.string());
  return a;
}

}  // namespace

namespace {

SimRunLog ToRunLog(const Dataset& data, int robots, const std::vector<std::optional<AgentLog>>& logs) {
  SimRunLog log;
  log.robots = robots;
  const auto n = static_cast<std::size_t>(robots);
  log.loads.resize(n);
  log.senders.resize(n);
  const SequenceSplit split = TeamSplit(data, robots);
  log.capture_time = split.CaptureTimes(data.fps);
  log.taker = split.owner;
  for (std::size_t s = 0; s < n; ++s) {
    if (!logs[s]) continue;
    const AgentLog& l = *logs[s];
    log.loads[s] = l.load;
    log.senders[s].medium_bytes = l.medium_wire_bytes;
    log.end = std::max(log.end, SimTime::Nanos(l.end_ns));
    for (const QueryRecord& q : l.queries) {
      log.queries.push_back(q);
      log.verify_requested += q.verify_requested ? 1 : 0;
      log.verify_accepted += q.verify_accepted.value_or(false) ? 1 : 0;
    }
    for (std::size_t d = 0; d < n; ++d) {
      if (d == s) continue;
      const AgentLinkCount& sent = l.sent[d];
      if (sent.messages == 0) continue;
      PairTraffic& pair = log.links.emplace_back();
      pair.src = static_cast<int>(s);
      pair.dst = static_cast<int>(d);
      LinkCounters& c = pair.counters;
      c.messages = static_cast<std::uint64_t>(sent.messages);
      c.payload_bytes = sent.payload_bytes;
      c.wire_bytes = sent.wire_bytes;
      const std::int64_t received = logs[d] ? logs[d]->received_from[s] : 0;
      c.delivered = static_cast<std::uint64_t>(std::min(received, sent.messages));
      c.dropped = c.messages - c.delivered;
    }
  }
  return log;
}

}  // namespace

GatheredRun GatherTeam(const ExperimentConfig& config, const SharedInputs& inputs, const std::string& strategy,
                       int robots, int run, const std::vector<std::optional<AgentLog>>& logs, double reference_auc) {
  if (logs.size() != static_cast<std::size_t>(robots)) throw std::invalid_argument("GatherTeam: one log slot per robot");
  for (std::size_t r = 0; r < logs.size(); ++r) {
    if (logs[r] && (logs[r]->robots != robots || logs[r]->robot != static_cast<int>(r) || logs[r]->run != run ||
                    logs[r]->strategy != strategy)) {
      throw std::runtime_error("agent log of robot " + std::to_string(r) + " is of another team (robot " +
                               std::to_string(logs[r]->robot) + " of " + std::to_string(logs[r]->robots) + ", run " +
                               std::to_string(logs[r]->run) + ", " + logs[r]->strategy + ")");
    }
  }
  const Dataset& data = inputs.deployment;
  const SimRunLog log = ToRunLog(data, robots, logs);
  const SimRunSummary summary = SummarizeSimRun(log, data.trajectory.positions, config.evaluation.radius_m,
                                                SuppressionWindow(data, config.evaluation.suppression_frames));
  NetworkVariant network;
  network.label.model = "lcm";
  RunSpec spec;
  spec.protocol = kLcmProtocol;
  spec.strategies = {ParseStrategy(strategy)};
  spec.robots = robots;
  spec.run = run;
  spec.seed = RunSeed(config.seed, robots, run);
  spec.network = &network;
  GatheredRun g;
  g.rows.runs.push_back(MakeRow(spec, strategy, summary, reference_auc));
  AppendRows(spec, strategy, log, summary, config, g.rows);
  g.auc = summary.auc;
  g.queries = summary.queries;
  g.incomplete = summary.latency.incomplete;
  for (std::size_t r = 0; r < logs.size(); ++r) {
    if (!logs[r]) g.missing_robots.push_back(static_cast<int>(r));
  }
  return g;
}

namespace {

struct LaunchedTeam {
  std::string strategy;
  std::vector<Child> children;
};

std::filesystem::path AgentFile(const std::filesystem::path& dir, const std::string& strategy, int robot,
                                const char* ext) {
  return dir / "agents" / (strategy + "_robot" + std::to_string(robot) + ext);
}

// Starts one agent per robot for `strategy` and waits for them (killing the ones still running
// at the timeout).
LaunchedTeam RunTeam(const LaunchOptions& o, std::uint64_t nonce, const std::filesystem::path& secret,
                     const ExperimentConfig& config, const std::string& strategy, const std::filesystem::path& dir,
                     std::ostream& out) {
  LaunchedTeam team{strategy, {}};
  for (int r = 0; r < o.robots; ++r) {
    const auto log = AgentFile(dir, strategy, r, ".log");
    std::filesystem::remove(log);  // a stale log must not pass for this run's
    team.children.push_back(Child{r, Spawn(AgentArgv(o, nonce, secret, strategy, r, log), AgentFile(dir, strategy, r, ".out"))});
  }
  out << "launch: " << strategy << ": " << o.robots << " agents started\n" << std::flush;
  // The frames' wall time, plus the agents' grace, plus start-up and barrier.
  const int frames = config.dataset.frames.value_or(1 << 20);
  const double timeout_s =
      o.timeout_s > 0 ? o.timeout_s : (frames / o.robots + 1) / config.dataset.fps / o.speedup + o.grace_s + 120;
  WaitAll(team.children,
          std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(timeout_s)));
  return team;
}

// Why an agent failed, in one line: the first line of its output that names an error (dvpr's
// own "dvpr: error: ..." or the LCM library's, which comes first when LCM cannot open), else
// its last line, else nothing.
std::string FirstErrorLine(const std::filesystem::path& output) {
  std::ifstream in(output);
  std::string line, last;
  while (std::getline(in, line)) {
    std::string lower = line;
    std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
    if (lower.find("error") != std::string::npos) return line;
    if (!line.empty()) last = line;
  }
  return last;
}

struct TeamLogs {
  std::vector<std::optional<AgentLog>> logs;
  bool clean = true;  // every agent exited 0 and left its log
  bool ran = false;   // at least one agent left a log: the team ran and has rows
};

// Reads the team's logs, lists each agent in agents.csv and prints why each failed one failed.
TeamLogs CollectTeam(const ExperimentConfig& config, const LaunchedTeam& team, int robots, const std::filesystem::path& dir,
                     std::ostream& agents_csv, std::ostream& out) {
  TeamLogs t;
  t.logs.resize(static_cast<std::size_t>(robots));
  for (const Child& c : team.children) {
    const auto path = AgentFile(dir, team.strategy, c.robot, ".log");
    auto& l = t.logs[static_cast<std::size_t>(c.robot)];
    const bool ok = WIFEXITED(c.status) && WEXITSTATUS(c.status) == 0 && !c.killed_at_timeout;
    if (ok && std::filesystem::exists(path)) l = ReadAgentLog(path);
    const bool dropped = DroppedOnPurpose(config, c);
    t.clean = t.clean && ((ok && l.has_value()) || dropped);
    t.ran = t.ran || l.has_value();
    std::int64_t incomplete = 0;
    if (l) {
      for (const auto& q : l->queries) incomplete += q.Complete() ? 0 : 1;
    }
    const auto count = [&](std::uint64_t AgentLog::*field) { return l ? std::to_string((*l).*field) : std::string(); };
    agents_csv << team.strategy << ',' << c.robot << ',' << Describe(c) << ',' << (l ? path.filename().string() : "")
               << ',' << (l ? std::to_string(l->queries.size()) : "") << ',' << (l ? std::to_string(incomplete) : "")
               << ',' << count(&AgentLog::malformed_datagrams) << ',' << count(&AgentLog::malformed) << ','
               << count(&AgentLog::foreign) << ',' << count(&AgentLog::duplicates) << ','
               << count(&AgentLog::kernel_dropped) << ',' << count(&AgentLog::out_of_range) << ','
               << count(&AgentLog::unauthenticated) << ',' << count(&AgentLog::held_dropped) << ','
               << count(&AgentLog::held_bytes_peak) << '\n';
    if (!ok && !dropped) {
      const std::string why = FirstErrorLine(AgentFile(dir, team.strategy, c.robot, ".out"));
      out << "launch: " << team.strategy << " robot " << c.robot << ": " << Describe(c)
          << (why.empty() ? std::string() : ": " + why) << "\n";
    }
  }
  return t;
}

// A team whose AUC is the reference of the others' relative AUC.
bool IsReference(const StrategySpec& s) { return s.broadcast() || s.bow == StrategySpec::Bow::kCentralized; }

void Append(RunOutput& all, const RunOutput& rows) {
  all.runs.insert(all.runs.end(), rows.runs.begin(), rows.runs.end());
  all.per_robot.insert(all.per_robot.end(), rows.per_robot.begin(), rows.per_robot.end());
  all.links.insert(all.links.end(), rows.links.begin(), rows.links.end());
  all.queries.insert(all.queries.end(), rows.queries.begin(), rows.queries.end());
  all.closure_pairs.insert(all.closure_pairs.end(), rows.closure_pairs.begin(), rows.closure_pairs.end());
}

void WriteLaunchFiles(const std::filesystem::path& dir, const ExperimentConfig& config, const RunOutput& all,
                      const std::string& agents_csv) {
  WriteFileAtomic(dir / "config.yaml", EmitConfig(config));
  WriteRunsCsv(dir / "runs.csv", all.runs);
  auto write = [&](const char* name, const char* header, const auto& rows) {
    std::string text = std::string(header) + "\n";
    for (const auto& r : rows) text += CsvRow(r) + "\n";
    WriteFileAtomic(dir / name, text);
  };
  write("per_robot.csv", kPerRobotHeader, all.per_robot);
  write("links.csv", kLinksHeader, all.links);
  if (config.outputs.queries) write("queries.csv", kQueriesHeader, all.queries);
  write("closure_pairs.csv", kClosurePairsHeader, all.closure_pairs);
  WriteFileAtomic(dir / "agents.csv", agents_csv);
  WriteFileAtomic(dir / "summary.json", SummaryJson(all.runs));
}

}  // namespace

int RunLaunch(const LaunchOptions& o, std::ostream& out) {
  o.Validate();
  const ExperimentConfig config = LoadConfig(o.config, o.overrides);
  CheckRealNetwork(config, o.config.string());
  const auto target = o.out.empty() ? std::filesystem::path("results") / (config.name + "_lcm") : o.out;
  // What every agent would find wrong is found here, once, before a process starts: the inputs
  // (each agent loads the same), the team size against the frames, the LCM URL.
  SharedInputs inputs = LoadSharedInputs(config, o.config.string());
  inputs.config = &config;
  FitTeamSize(o.robots, inputs.deployment);
  CheckDescriptorsFitTheWire(inputs.deployment, o.config.string());
  { const LcmTransport probe(o.lcm_url.empty() ? kDefaultLcmUrl : o.lcm_url); }
  // Agents write into the temporary folder; the target appears only if some team ran.
  ResultFolder folder(target);
  const std::filesystem::path dir = folder.dir();
  CreateOutputDir(dir / "agents");
  // The references first: broadcast's AUC is every descriptor strategy's reference, the BoW
  // server's (bow_centralized) every bow_ strategy's (docs/bow.md).
  std::vector<StrategySpec> strategies = config.sweep.strategies;
  std::stable_partition(strategies.begin(), strategies.end(), [](const StrategySpec& s) { return IsReference(s); });
  const std::uint64_t nonce = DrawTeamNonce();
  // A fresh secret for this launch's teams, in a file only this user can read, in a folder of its
  // own outside the results; removed when the teams are done (docs/security.md).
  const auth::SecretFolder secret_folder(std::filesystem::temp_directory_path());
  const std::filesystem::path secret = secret_folder.path() / "team.secret";
  auth::WriteSecretFile(secret, auth::DrawSecret());
  std::vector<LaunchedTeam> teams;
  for (const StrategySpec& spec : strategies) teams.push_back(RunTeam(o, nonce, secret, config, spec.name, dir, out));

  RunOutput all;
  std::ostringstream agents_csv;
  agents_csv << "strategy,robot,exit,log,queries,incomplete,malformed_datagrams,malformed_messages,foreign,"
                "duplicates,kernel_dropped,out_of_range,unauthenticated,held_dropped,held_bytes_peak\n";
  double reference_auc = kNotApplicable, bow_reference_auc = kNotApplicable;
  bool clean = true;
  for (const LaunchedTeam& team : teams) {
    const TeamLogs t = CollectTeam(config, team, o.robots, dir, agents_csv, out);
    clean = clean && t.clean;
    if (!t.ran) {  // no agent left a log: rows of zeros would pass for a run
      out << "launch: " << team.strategy << ": no agent ran, no rows written\n";
      continue;
    }
    const StrategySpec spec = ParseStrategy(team.strategy);
    double& reference = spec.bag_of_words() ? bow_reference_auc : reference_auc;
    GatheredRun g = GatherTeam(config, inputs, team.strategy, o.robots, o.run, t.logs, reference);
    if (IsReference(spec)) {
      reference = g.auc;
      g.rows.runs.front().auc_reference = g.auc;
      g.rows.runs.front().relative_auc = RelativeAuc(g.auc, g.auc);
    }
    out << "launch: " << team.strategy << ": " << g.queries << " queries, " << g.incomplete
        << " with a reply missing, auc " << FormatDouble(g.auc, 4) << "\n";
    Append(all, g.rows);
  }
  if (all.runs.empty()) {  // the folder's destructor removes the temporary folder
    throw std::runtime_error(target.string() + ": no team ran (no agent left a log; why each failed is above); "
                             "nothing written");
  }
  WriteLaunchFiles(dir, config, all, agents_csv.str());
  folder.Commit();
  out << "results in " << target.string() << "\n";
  return clean ? 0 : 1;
}

}  // namespace dvpr
