#include "experiments/app/cli.h"

#include <filesystem>
#include <stdexcept>

#include "dvpr/version.h"
#include "experiments/protocols/lcm/agent_process.h"
#include "experiments/config/config.h"
#include "experiments/app/experiment.h"
#include "experiments/arch/dispatch.h"
#include "experiments/figures/figures.h"
#include "experiments/protocols/lcm/lcm_launch.h"
#include "experiments/sweep/run_executor.h"

namespace dvpr {

namespace {

constexpr const char* kUsage = R"(dvpr: discrete-event simulator of decentralized visual place recognition

Usage:
  dvpr run CONFIG.yaml [--out DIR] [--set key.path=value ...] [--threads N] [--quiet]
                     expand the config's sweep, run it on all cores, write DIR
                     (default results/<config name>): config.yaml, runs.csv,
                     per_robot.csv, links.csv, summary.json, figures/*.png;
                     DIR appears (an earlier result folder is replaced whole)
                     only when all succeeded; other existing folders are refused
  dvpr plot DIR      redraw DIR/figures/*.png from the files in DIR
  dvpr agent --config C --robot R [--robots N] [--run K] [--strategy S] [--lcm URL]
             [--speedup X] [--out FILE] [--set key.path=value ...] [--grace SEC]
                     one robot as a real process over LCM (UDP multicast), in
                     wall-clock time at the config's fps x speedup; writes its log
  dvpr launch --config C --robots N [--run K] [--out DIR] [--lcm URL] [--speedup X]
              [--set key.path=value ...] [--grace SEC] [--timeout SEC]
                     N agent processes on this machine, each configured strategy
                     in turn; gathers their logs into DIR (default
                     results/<config name>_lcm) with protocol=lcm
  dvpr --help        this text
  dvpr --version     the version

Examples:
  dvpr run experiments/configs/paper_kitti00.yaml
  dvpr run experiments/configs/paper_kitti00.yaml --set runs=2 --set robots={from: 2, to: 6}
  dvpr launch --config experiments/configs/paper_kitti00.yaml --robots 4 --speedup 5 \
              --set dataset.frames=600 --set evaluation.suppression_frames=50
)";

struct RunArgs {
  std::filesystem::path config;
  std::filesystem::path out;
  std::vector<ConfigOverride> overrides;
  ExecutorOptions options;
};

RunArgs ParseRunArgs(const std::vector<std::string>& args) {
  RunArgs r;
  for (std::size_t i = 1; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&]() -> const std::string& {
      if (i + 1 >= args.size()) throw std::invalid_argument(a + " needs a value");
      return args[++i];
    };
    if (a == "--out") {
      r.out = value();
    } else if (a == "--set") {
      r.overrides.push_back(ParseOverride(value()));
    } else if (a == "--threads") {
      r.options.threads = std::stoi(value());
    } else if (a == "--quiet") {
      r.options.progress = false;
    } else if (!a.empty() && a[0] == '-') {
      throw std::invalid_argument("unknown option " + a);
    } else if (r.config.empty()) {
      r.config = a;
    } else {
      throw std::invalid_argument("more than one config file (" + r.config.string() + ", " + a + ")");
    }
  }
  if (r.config.empty()) throw std::invalid_argument("dvpr run needs a CONFIG.yaml");
  return r;
}

int Run(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  RunArgs a;
  try {
    a = ParseRunArgs(args);
  } catch (const std::invalid_argument& e) {
    err << "dvpr run: " << e.what() << " (see dvpr --help)\n";
    return 2;
  }
  const ExperimentConfig config = LoadConfig(a.config, a.overrides);
  const auto dir = a.out.empty() ? std::filesystem::path("results") / config.name : a.out;
  RunExperiment(config, a.config.string(), dir, BuiltinProtocols(), a.options, out);
  out << "results in " << dir.string() << "\n";
  return 0;
}

int Plot(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  if (args.size() != 2) {
    err << "dvpr plot: expected one folder (see dvpr --help)\n";
    return 2;
  }
  const std::filesystem::path dir = args[1];
  if (!std::filesystem::exists(dir / "runs.csv")) {
    throw std::runtime_error(dir.string() + ": no runs.csv (is this a dvpr run folder?)");
  }
  for (const auto& png : DrawFigures(dir, err)) out << png.string() << "\n";
  return 0;
}

// Parses a subcommand's options; bad usage is exit status 2, as for dvpr run.
template <typename Parse, typename Body>
int WithOptions(const char* name, const std::vector<std::string>& args, std::ostream& err, Parse parse, Body body) {
  decltype(parse(args)) options;
  try {
    options = parse(args);
  } catch (const std::invalid_argument& e) {
    err << "dvpr " << name << ": " << e.what() << " (see dvpr --help)\n";
    return 2;
  }
  return body(options);
}

}  // namespace

int RunCli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  if (args.empty()) {
    err << kUsage;
    return 2;
  }
  const std::string& cmd = args[0];
  if (cmd == "--help" || cmd == "-h" || cmd == "help") {
    out << kUsage;
    return 0;
  }
  if (cmd == "--version") {
    out << "dvpr " << kVersion << " (" << CompiledArch() << ")\n";  // which build runs: see dispatch.h
    return 0;
  }
  try {
    if (cmd == "run") return Run(args, out, err);
    if (cmd == "plot") return Plot(args, out, err);
    if (cmd == "agent") {
      return WithOptions("agent", args, err, ParseAgentArgs,
                         [&](const AgentProcessOptions& o) { return RunAgentProcess(o, out); });
    }
    if (cmd == "launch") {
      return WithOptions("launch", args, err, ParseLaunchArgs, [&](const LaunchOptions& o) { return RunLaunch(o, out); });
    }
  } catch (const std::exception& e) {
    err << "dvpr: error: " << e.what() << "\n";
    return 1;
  }
  err << "dvpr: unknown command '" << cmd << "' (see dvpr --help)\n";
  return 2;
}

}  // namespace dvpr
