#include "experiments/replay/replay.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "experiments/config/config.h"
#include "experiments/config/network_variants.h"
#include "experiments/config/option_reader.h"
#include "experiments/replay/replay_page.h"
#include "experiments/replay/replay_tracks.h"
#include "experiments/results/manifest.h"
#include "experiments/results/one_line_text.h"
#include "experiments/results/result_writers.h"
#include "experiments/results/safe_output.h"

namespace dvpr::replay {

namespace {

int Count(OptionReader& in) {
  const std::string flag = in.flag();
  const int v = in.Int();
  if (v < 0) throw std::invalid_argument(flag + ": expected a number >= 0, got " + std::to_string(v));
  return v;
}

void CheckFolder(const std::filesystem::path& dir) {
  if (!std::filesystem::exists(dir)) throw std::runtime_error(dir.string() + ": no such result folder");
  if (!std::filesystem::is_directory(dir)) throw std::runtime_error(dir.string() + ": not a folder (expected a result folder)");
  if (!std::filesystem::exists(dir / "messages.csv")) {
    throw std::runtime_error(dir.string() + ": no messages.csv (record it: dvpr run CONFIG --set outputs.messages=true)");
  }
}

// The page may replace only what an earlier `dvpr replay` wrote (README "Result folders"): nothing
// at `file`, or a regular file that starts with kReplayPageMarker. Not a link, not runs.csv.
void CheckTarget(const std::filesystem::path& file) {
  const std::string name = file.string();
  const std::string refused = "; dvpr replay writes only a new file or over an earlier replay page: choose another --out";
  struct stat st {};
  if (::lstat(file.c_str(), &st) != 0) {
    if (errno == ENOENT) return;
    throw std::runtime_error(name + ": cannot check the output file (" + std::strerror(errno) + ")");
  }
  if (S_ISLNK(st.st_mode)) throw std::runtime_error(name + ": is a symbolic link" + refused);
  if (!S_ISREG(st.st_mode)) throw std::runtime_error(name + ": exists and is not a file" + refused);
  const std::string marker = kReplayPageMarker;
  std::string head(marker.size(), '\0');
  const int fd = ::open(file.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
  const ssize_t n = fd < 0 ? -1 : ::read(fd, head.data(), head.size());
  if (fd >= 0) ::close(fd);
  if (n != static_cast<ssize_t>(head.size()) || head != marker) {
    throw std::runtime_error(name + ": exists and is not a replay page" + refused);
  }
}

std::string Strategies(const ReplayRun& run) {
  std::string s;
  for (const auto& m : run.strategies) s += (s.empty() ? "" : " vs ") + m.strategy;
  return s;
}

}  // namespace

ReplayOptions ParseReplayArgs(const std::vector<std::string>& args) {
  ReplayOptions o;
  OptionReader in(args);
  while (in.Next()) {
    const std::string& f = in.flag();
    if (f == "--robots") o.selection.robots = Count(in);
    else if (f == "--run") o.selection.run = Count(in);
    else if (f == "--network") o.selection.network = Count(in);
    else if (f == "--strategy") o.selection.strategies.push_back(in.Text());
    else if (f == "--out") o.out = in.Text();
    else if (!f.empty() && f[0] == '-') in.Unknown();
    else if (o.dir.empty()) o.dir = f;
    else throw std::invalid_argument("more than one result folder (" + o.dir.string() + ", " + f + ")");
  }
  if (o.dir.empty()) throw std::invalid_argument("dvpr replay needs a RESULT_DIR");
  return o;
}

std::filesystem::path WriteReplay(const ReplayOptions& options, std::ostream& out) {
  CheckFolder(options.dir);
  const std::filesystem::path config_yaml = options.dir / "config.yaml";
  const ExperimentConfig config = LoadFolderConfig(config_yaml);
  const ReplayRun run = ReadReplayRun(options.dir / "messages.csv", options.selection, VariantLabels(config.network));
  const Tracks tracks = TracksOf(config, config_yaml, run.robots);
  const std::filesystem::path file =
      !options.out.empty() ? options.out
                           : options.dir / ("replay_n" + std::to_string(run.robots) + "_run" + std::to_string(run.run) +
                                            "_net" + std::to_string(run.network_variant) + ".html");
  CheckTarget(file);
  const std::string page = ReplayPage(run, tracks);
  {
    const OutputDir folder = OutputDir::Open(file.parent_path());
    WriteFileAt(folder, file.filename().string(), page);
    AddToManifest(folder, {file.filename().string()});  // a page in a result folder is dvpr's
  }
  std::size_t messages = 0;
  for (const auto& s : run.strategies) messages += s.messages.size();
  // The names come from the folder (config.yaml, messages.csv) and the path from the user: shown
  // on one line, control characters and bytes that are not UTF-8 as visible escapes.
  out << "replay of " << OneLineText(tracks.name) << ": " << run.robots << " robots, run " << run.run
      << ", network " << run.network_variant << " (" << OneLineText(NetworkName(run.network, NameStyle::kPage)) << "), "
      << OneLineText(Strategies(run)) << ", " << messages << " messages: " << OneLineText(file.string()) << " ("
      << (page.size() + 512) / 1024 << " KiB)\n";
  return file;
}

}  // namespace dvpr::replay
