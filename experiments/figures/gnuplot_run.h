#pragma once
// Drawing one figure: gnuplot started directly (posix_spawn with an argument vector, never a
// shell, so no path or name is ever parsed as a command), its PNG checked before it replaces
// the earlier one.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace dvpr {

// The first executable regular file `name` in a folder of $PATH (or of /usr/bin:/bin when it is
// unset), as `command -v` finds it; nullopt when there is none. Empty entries of $PATH (the
// current folder by an old convention) are skipped.
std::optional<std::filesystem::path> FindProgram(std::string_view name);

// Runs `program` with arguments `argv` (argv[0] included) inside folder `dir`, its standard
// input /dev/null, output to `out_fd`, errors to `err_fd`, and waits for it. Returns "" when it
// exited with status 0, else what happened ("exit status 1", "killed by signal 9", "cannot start
// it: ..."). Throws nothing.
std::string RunProgram(const std::filesystem::path& program, const std::vector<std::string>& argv,
                       const std::filesystem::path& dir, int out_fd, int err_fd);

// Whether a figure's log outlives a failure: kKept for `dvpr plot` (the folder stays), kGone for
// `dvpr run` (a failed run removes its temporary folder, log and all, so no message names it).
enum class FigureLog { kKept, kGone };

// Runs gnuplot on script `gp` (a file in `data_dir`, run there) and puts its PNG at `png`,
// replacing an earlier one only when gnuplot exited with status 0 and wrote a whole PNG (the
// signature first, the IEND chunk last). Both files are written through safe_output.h's
// AtomicFile (a private temporary renamed into place; no link is followed): gnuplot's stderr
// reaches `log` only when the figure was not drawn, and an earlier `log` is removed when it was.
// When it was not, throws std::runtime_error naming `png` and what happened: gnuplot's exit with
// its first words, or a file system too full to hold the PNG (with the bytes free: gnuplot's
// warnings are not quoted then, a good draw prints them too), and `log` when it is kept and could
// be written; the earlier PNG then stays as it was.
void DrawWithGnuplot(const std::filesystem::path& gnuplot, const std::filesystem::path& data_dir,
                     const std::filesystem::path& gp, const std::filesystem::path& png,
                     const std::filesystem::path& log, FigureLog kept = FigureLog::kKept);

}  // namespace dvpr
