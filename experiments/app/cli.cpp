#include "experiments/app/cli.h"

#include <exception>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "dvpr/version.h"
#include "experiments/protocols/lcm/agent_process.h"
#include "experiments/config/config.h"
#include "experiments/config/option_reader.h"
#include "experiments/app/experiment.h"
#include "experiments/app/plot_command.h"
#include "experiments/app/run_on_ranks.h"
#include "experiments/arch/dispatch.h"
#include "experiments/figures/figures.h"
#include "experiments/mpi/mpi_run_distributor.h"
#include "experiments/mpi/mpi_world.h"
#include "experiments/protocols/inputs.h"
#include "experiments/protocols/lcm/lcm_launch.h"
#include "experiments/replay/replay.h"
#include "experiments/results/result_folder.h"
#include "experiments/results/one_line_text.h"
#include "experiments/sweep/run_executor.h"

namespace dvpr {

namespace {

// A message kept to one line: it may quote a name, a path or a library's text, so line breaks,
// control characters (a terminal's escape sequences) and bytes that are not UTF-8 are shown as
// visible escapes (one_line_text.h).
std::string OneLine(std::string_view message) { return OneLineText(message); }

constexpr const char* kUsage = R"(dvpr: discrete-event simulator of decentralized visual place recognition

Usage:
  dvpr run CONFIG.yaml [--out DIR] [--set key.path=value ...] [--threads N] [--quiet]
           [--allow-large]
                     expand the config's sweep, run it on all cores, write DIR
                     (default results/<config name>): config.yaml, runs.csv,
                     per_robot.csv, links.csv, summary.json, figures/*.png;
                     DIR appears (an earlier result folder is replaced whole)
                     only when all succeeded; other existing folders are refused;
                     --allow-large runs a sweep refused as too large (over 1e6 runs,
                     or a run that may need more than the machine's memory)
  mpirun -n K dvpr run CONFIG.yaml [...]   (or srun on a cluster)
                     the same sweep, its runs spread over K MPI ranks; rank 0
                     writes DIR, the same files as a single process, byte for byte
  dvpr plot DIR      redraw DIR/figures/*.png from the files in DIR
  dvpr descriptors CONFIG.yaml --out DIR [--set key.path=value ...]
                     write the deployment descriptors of the config's team plan,
                     one DIR/robot<r>.npy per robot (what dataset.trajectories[r].
                     descriptors reads back; docs/config.md "Team plans")
  dvpr agent --config C --robot R [--robots N] [--run K] [--strategy S] [--lcm URL]
             [--speedup X] [--out FILE] [--set key.path=value ...] [--grace SEC]
             [--team-nonce HEX] --team-secret FILE [--hold-bytes B]
                     one robot as a real process over LCM (UDP multicast, udpm://
                     URLs only), in wall-clock time at the config's fps x speedup;
                     writes its log; agents with another --team-nonce (dvpr launch
                     draws one per launch) are another team; every message is
                     tagged with the secret in FILE (64 hex digits, mode 0600) and
                     only messages tagged with it are taken (docs/security.md);
                     --hold-bytes bounds what it keeps while it waits (16 MiB)
  dvpr launch --config C --robots N [--run K] [--out DIR] [--lcm URL] [--speedup X]
              [--set key.path=value ...] [--grace SEC] [--timeout SEC] [--hold-bytes B]
                     N agent processes on this machine, each configured strategy
                     in turn, with a fresh team secret per launch; gathers their
                     logs into DIR (default results/<config name>_lcm) with
                     protocol=lcm
  dvpr replay RESULT_DIR [--robots N] [--run K] [--network V] [--strategy S ...]
              [--out FILE]
                     one self-contained HTML page replaying a simulated run of
                     RESULT_DIR (needs outputs.messages: true): robots moving,
                     messages travelling (coloured by role), queues, bytes of
                     each strategy; default FILE RESULT_DIR/replay_n<N>_run<K>_net<V>.html,
                     default run the first in messages.csv; open FILE#t=12.5 for
                     that instant (docs/replay.md)
  dvpr --help        this text
  dvpr --version     the version

Exit status:
  0  success
  1  an input you can fix: a config key, a data or centroid file, the output folder;
     one line on stderr "dvpr: error: <file>: <key.path>: <problem>" (nothing is written
     when it is found before the run starts, as everything that can be checked is);
     dvpr launch also when an agent did not exit cleanly: its first error line is
     printed; the teams that ran are written, a team no agent of which ran has no
     rows, and when none ran nothing is written
  2  usage: an unknown command or flag, a missing argument, a flag value that is not
     what the flag takes (e.g. --threads abc, --threads -3, --out '')
  3  internal error: a bug in dvpr, not in your input ("dvpr: internal error: ..."); please
     report it with the config and command line. A crash (a signal) is never 0, 1 or 2.

Examples:
  dvpr run experiments/configs/paper_kitti00.yaml
  dvpr run experiments/configs/paper_kitti00.yaml --set runs=2 --set 'robots={from: 2, to: 6}'
  dvpr launch --config experiments/configs/paper_kitti00.yaml --robots 4 --speedup 5 \
              --set dataset.frames=1700 --set evaluation.suppression_frames=50
  dvpr replay results/replay_demo
)";

struct RunArgs {
  std::filesystem::path config;
  std::filesystem::path out;
  std::vector<ConfigOverride> overrides;
  ExecutorOptions options;
};

// Flag values are checked here, so a bad one is a usage error (exit 2) naming the flag.
RunArgs ParseRunArgs(const std::vector<std::string>& args) {
  RunArgs r;
  OptionReader in(args);
  while (in.Next()) {
    const std::string& f = in.flag();
    if (f == "--out") {
      r.out = in.Text();
    } else if (f == "--set") {
      r.overrides.push_back(ParseOverride(in.Text()));
    } else if (f == "--threads") {
      r.options.threads = in.Int();
      if (r.options.threads < 0) {
        throw std::invalid_argument("--threads: expected a count >= 0 (0: all cores), got " +
                                    std::to_string(r.options.threads));
      }
    } else if (f == "--quiet") {
      r.options.progress = false;
    } else if (f == "--allow-large") {
      r.options.allow_large = true;
    } else if (!f.empty() && f[0] == '-') {
      in.Unknown();
    } else if (r.config.empty()) {
      r.config = f;
    } else {
      throw std::invalid_argument("more than one config file (" + r.config.string() + ", " + f + ")");
    }
  }
  if (r.config.empty()) throw std::invalid_argument("dvpr run needs a CONFIG.yaml");
  return r;
}

int Run(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  RunArgs a;
  // Under an MPI launcher every rank parses the same arguments: rank 0 alone says what is wrong
  // and returns the usage status. The others return 0: a non-zero status from any of them makes
  // the launcher end the job, rank 0 too, perhaps before its line is out (seen with 3 ranks under
  // load: status 2 and no line); the job's status is rank 0's.
  const bool speaks = LauncherRank() == 0;
  try {
    a = ParseRunArgs(args);
  } catch (const std::invalid_argument& e) {
    if (speaks) err << "dvpr run: " << OneLine(e.what()) << " (see dvpr --help)\n";
    return speaks ? kExitUsage : kExitOk;
  } catch (const ConfigError& e) {  // a malformed --set
    if (speaks) err << "dvpr run: " << OneLine(e.what()) << " (see dvpr --help)\n";
    return speaks ? kExitUsage : kExitOk;
  }
  const auto run = [&a](const ExecutorOptions& options, std::ostream& summary) {
    const ExperimentConfig config = LoadConfig(a.config, a.overrides);
    const auto dir = a.out.empty() ? std::filesystem::path("results") / config.name : a.out;
    RunExperiment(config, a.config.string(), dir, BuiltinProtocols(), options, summary);
    summary << "results in " << dir.string() << "\n";
    return kExitOk;
  };
  const MpiWorld world;  // one of several ranks under mpirun or srun (experiments/mpi/mpi_world.h)
  if (world.joined() && world.rank() == 0 && a.options.threads == 0) {
    err << BoundCoresNote(MachineCores(), BoundCores(), world.local_size());
  }
  if (!world.distributed()) return run(a.options, out);
  return RunOnRanks(world, a.options, run, out, err);
}

struct DescriptorsArgs {
  std::filesystem::path config;
  std::filesystem::path out;
  std::vector<ConfigOverride> overrides;
};

DescriptorsArgs ParseDescriptorsArgs(const std::vector<std::string>& args) {
  DescriptorsArgs d;
  OptionReader in(args);
  while (in.Next()) {
    const std::string& f = in.flag();
    if (f == "--out") {
      d.out = in.Text();
    } else if (f == "--set") {
      d.overrides.push_back(ParseOverride(in.Text()));
    } else if (!f.empty() && f[0] == '-') {
      in.Unknown();
    } else if (d.config.empty()) {
      d.config = f;
    } else {
      throw std::invalid_argument("more than one config file (" + d.config.string() + ", " + f + ")");
    }
  }
  if (d.config.empty()) throw std::invalid_argument("dvpr descriptors needs a CONFIG.yaml");
  if (d.out.empty()) throw std::invalid_argument("--out: dvpr descriptors needs the folder to write");
  return d;
}

// The deployment descriptors of a team plan, one .npy per robot, into a folder that appears whole
// (ResultFolder): how a synthetic team becomes a team with descriptor files of its own.
int WriteDescriptors(const DescriptorsArgs& a, std::ostream& out) {
  const ExperimentConfig config = LoadConfig(a.config, a.overrides);
  if (!config.dataset.Planned()) {
    throw ConfigError(a.config.string() + ": dataset: dvpr descriptors writes a team plan's robots' descriptors; "
                      "the config has neither dataset.trajectories nor a dataset.scenario other than split");
  }
  const SharedInputs inputs = LoadSharedInputs(config, a.config.string());
  ResultFolder folder(a.out);
  const std::vector<std::filesystem::path> files = WriteRobotDescriptors(inputs.deployment, folder.dir());
  folder.Commit();
  for (const auto& f : files) out << OneLineText((a.out / f.filename()).string()) << "\n";
  return kExitOk;
}

int Plot(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  if (args.size() != 2) {
    err << "dvpr plot: expected one folder (see dvpr --help)\n";
    return kExitUsage;
  }
  for (const auto& png : PlotFolder(args[1], err)) out << OneLineText(png.string()) << "\n";
  return kExitOk;
}

// Parses a subcommand's options; bad usage is exit status 2, as for dvpr run.
template <typename Parse, typename Body>
int WithOptions(const char* name, const std::vector<std::string>& args, std::ostream& err, Parse parse, Body body) {
  decltype(parse(args)) options;
  try {
    options = parse(args);
  } catch (const std::invalid_argument& e) {
    err << "dvpr " << name << ": " << OneLine(e.what()) << " (see dvpr --help)\n";
    return kExitUsage;
  } catch (const ConfigError& e) {  // a malformed --set
    err << "dvpr " << name << ": " << OneLine(e.what()) << " (see dvpr --help)\n";
    return kExitUsage;
  }
  return body(options);
}

// The subcommand `cmd`; nullopt when there is none of that name.
std::optional<int> Dispatch(const std::string& cmd, const std::vector<std::string>& args, std::ostream& out,
                            std::ostream& err) {
  if (cmd == "run") return Run(args, out, err);
  if (cmd == "plot") return Plot(args, out, err);
  if (cmd == "agent") {
    return WithOptions("agent", args, err, ParseAgentArgs,
                       [&](const AgentProcessOptions& o) { return RunAgentProcess(o, out); });
  }
  if (cmd == "replay") {
    return WithOptions("replay", args, err, replay::ParseReplayArgs, [&](const replay::ReplayOptions& o) {
      replay::WriteReplay(o, out);
      return kExitOk;
    });
  }
  if (cmd == "descriptors") {
    return WithOptions("descriptors", args, err, ParseDescriptorsArgs,
                       [&](const DescriptorsArgs& a) { return WriteDescriptors(a, out); });
  }
  if (cmd == "launch") {
    return WithOptions("launch", args, err, ParseLaunchArgs, [&](const LaunchOptions& o) { return RunLaunch(o, out); });
  }
  return std::nullopt;
}

}  // namespace

// What the user can fix is a ConfigError, a std::invalid_argument (a parameter struct's
// Validate) or another std::runtime_error (files, I/O, std::filesystem); any other exception
// (std::logic_error, std::bad_alloc, ...) is dvpr's own fault and must not look like one of those.
//
// The message goes out in one write: std::cerr flushes after every <<, and under mpirun a rank's
// stderr is forwarded in the chunks it was written in, so mpirun's own MPI_ABORT banner could
// land between the pieces of a line written piece by piece.
int ReportError(std::exception_ptr error, std::ostream& err) {
  std::string line;
  int status = kExitInternal;
  try {
    std::rethrow_exception(error);
  } catch (const std::invalid_argument& e) {
    line = "dvpr: error: " + OneLine(e.what()) + "\n";
    status = kExitInput;
  } catch (const std::runtime_error& e) {
    line = "dvpr: error: " + OneLine(e.what()) + "\n";
    status = kExitInput;
  } catch (const std::exception& e) {
    line = "dvpr: internal error: " + OneLine(e.what()) + " (a bug in dvpr; please report it)\n";
  } catch (...) {
    line = "dvpr: internal error: an unknown exception (a bug in dvpr; please report it)\n";
  }
  err << line << std::flush;
  return status;
}

int RunCli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  if (args.empty()) {
    err << kUsage;
    return kExitUsage;
  }
  const std::string& cmd = args[0];
  if (cmd == "--help" || cmd == "-h" || cmd == "help") {
    out << kUsage;
    return kExitOk;
  }
  if (cmd == "--version") {
    out << "dvpr " << kVersion << " (" << CompiledArch() << ")\n";  // which build runs: see dispatch.h
    return kExitOk;
  }
  try {
    if (const std::optional<int> status = Dispatch(cmd, args, out, err)) return *status;
  } catch (...) {
    return ReportError(std::current_exception(), err);
  }
  err << "dvpr: unknown command '" << OneLine(cmd) << "' (see dvpr --help)\n";
  return kExitUsage;
}

}  // namespace dvpr
