#pragma once
// `dvpr replay RESULT_DIR`: one self-contained HTML page that replays a
// simulated run of a result folder - robots driving, messages travelling,
// queues, cumulative bytes per strategy (docs/replay.md).
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "experiments/replay/replay_messages.h"

namespace dvpr::replay {

struct ReplayOptions {
  std::filesystem::path dir;  // the result folder (messages.csv, config.yaml)
  std::filesystem::path out;  // empty: dir/replay_n<robots>_run<run>_net<variant>.html
  Selection selection;
};

// args[0] is "replay". Throws std::invalid_argument (a usage error) naming the flag.
ReplayOptions ParseReplayArgs(const std::vector<std::string>& args);

// How every replay page begins: `dvpr replay` writes over an existing file only when it starts
// with this (an earlier page), never over runs.csv or any other file.
inline constexpr const char* kReplayPageMarker = "<!DOCTYPE html>\n<!-- dvpr replay: written by `dvpr replay`";

// Writes the page atomically (nothing, or the whole file) and says on `out` what it replays and
// where. Throws std::runtime_error, one line naming the file at fault, for a missing folder, a
// folder without messages.csv, a selection the folder does not hold, an unreadable pose file, an
// output file that exists and is not an earlier replay page (or is a symbolic link).
std::filesystem::path WriteReplay(const ReplayOptions& options, std::ostream& out);

}  // namespace dvpr::replay
