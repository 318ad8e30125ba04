#pragma once
// The dvpr subcommands (DESIGN.md section 6). main.cpp only dispatches to RunCli.
#include <ostream>
#include <string>
#include <vector>

namespace dvpr {

// Runs `dvpr <args...>` (args without the program name). Returns the exit status: 0 success,
// 1 an error (one line on `err`: "dvpr: error: <file>: <key.path>: <problem>"), 2 bad usage.
int RunCli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace dvpr
