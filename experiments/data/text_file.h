#pragma once
// Reading the text data files (loaders.cpp, robot_trajectory.cpp): lines, numbers and fields,
// every fault a std::runtime_error naming the file and the 1-based line.
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace dvpr::text_file {

[[noreturn]] void Fail(const std::filesystem::path& path, const std::string& what);
[[noreturn]] void FailLine(const std::filesystem::path& path, std::size_t line, const std::string& what);
std::string_view Trim(std::string_view s);
// The file's lines without their terminators (LF or CRLF); trailing blank lines are dropped, a
// blank line before the last non-blank one is an error (it would shift every later frame).
std::vector<std::string> ReadLines(const std::filesystem::path& path);
// One number; NaN and Inf are rejected here so no caller has to remember to.
double ParseNumber(const std::filesystem::path& path, std::size_t line, std::string_view token);
std::vector<std::string_view> SplitWhitespace(std::string_view s);
std::vector<std::string_view> SplitCommas(std::string_view s);

}  // namespace dvpr::text_file
