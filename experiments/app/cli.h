#pragma once
// The dvpr subcommands (docs/design.md section 6). main.cpp only dispatches to RunCli.
#include <exception>
#include <ostream>
#include <string>
#include <vector>

namespace dvpr {

// The exit statuses of dvpr, as `dvpr --help` documents them.
inline constexpr int kExitOk = 0;
inline constexpr int kExitInput = 1;     // an input the user can fix: "dvpr: error: <file>: <key.path>: <problem>"
inline constexpr int kExitUsage = 2;     // unknown command or flag, missing argument, malformed flag value
inline constexpr int kExitInternal = 3;  // an exception that is not about the input: a bug ("dvpr: internal error: ...")

// Runs `dvpr <args...>` (args without the program name). Returns the exit status above, with one
// line on `err` for statuses 1 to 3. A subcommand may return 1 itself (dvpr launch, when an
// agent did not exit cleanly).
int RunCli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

// The exit status of an exception that escaped a subcommand, its one line written to `err`:
// std::invalid_argument and std::runtime_error (ConfigError, file and I/O errors) are inputs the
// user can fix (1, "dvpr: error: ..."); anything else is a bug (3, "dvpr: internal error: ...").
int ReportError(std::exception_ptr error, std::ostream& err);

}  // namespace dvpr
