#pragma once
// Reading the text data files (loaders.cpp, robot_trajectory.cpp): lines, numbers and fields,
// every fault a std::runtime_error naming the file and the 1-based line. Text quoted from a file
// in a message is made printable (printable.h).
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace dvpr::text_file {

[[noreturn]] void Fail(const std::filesystem::path& path, const std::string& what);
[[noreturn]] void FailLine(const std::filesystem::path& path, std::size_t line, const std::string& what);
std::string_view Trim(std::string_view s);
// What keeps `path` from being read as a data file, found by stat without opening it (opening a
// FIFO would wait for a writer): "" for a regular file or a symbolic link to one, else "no such
// file", "is a folder, not a regular file", "is a FIFO, not a regular file", "is a device, not a
// regular file", "is a socket, not a regular file", "is a loop of symbolic links" or "cannot be
// examined (<reason>)".
std::string NotARegularFile(const std::filesystem::path& path);
inline constexpr std::string_view kNoSuchFile = "no such file";  // NotARegularFile's answer for nothing there
// NotARegularFile's answer when something is at `path` but not a regular file, else "": what a
// reader refuses before opening (a missing file is left to its open, which says it cannot).
std::string ThereButNotARegularFile(const std::filesystem::path& path);
// `line` without a leading UTF-8 byte-order mark (EF BB BF), which some editors write before a
// CSV header; the readers strip it from a file's first line.
std::string_view WithoutByteOrderMark(std::string_view line);
// The file's lines without their terminators (LF or CRLF) or a leading byte-order mark; trailing
// blank lines are dropped, a blank line before the last non-blank one is an error (it would shift
// every later frame). A path that is there but not a regular file (ThereButNotARegularFile) is
// refused unopened.
std::vector<std::string> ReadLines(const std::filesystem::path& path);
// One number; NaN and Inf are rejected here so no caller has to remember to.
double ParseNumber(const std::filesystem::path& path, std::size_t line, std::string_view token);
std::vector<std::string_view> SplitWhitespace(std::string_view s);
std::vector<std::string_view> SplitCommas(std::string_view s);

}  // namespace dvpr::text_file
