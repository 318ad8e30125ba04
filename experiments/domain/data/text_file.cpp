// Reading the text data files (text_file.h).
#include "experiments/domain/data/text_file.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <stdexcept>
#include <system_error>

#include "experiments/domain/data/printable.h"

namespace dvpr::text_file {

namespace fs = std::filesystem;

[[noreturn]] void Fail(const fs::path& path, const std::string& what) {
  throw std::runtime_error(path.string() + ": " + what);
}
[[noreturn]] void FailLine(const fs::path& path, std::size_t line, const std::string& what) {
  Fail(path, "line " + std::to_string(line) + ": " + what);
}

std::string_view Trim(std::string_view s) {
  const auto is_space = [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; };
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
  return s;
}

// By stat: a FIFO is never opened, so a reader never waits for a writer that does not come.
std::string NotARegularFile(const fs::path& path) {
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (ec == std::errc::too_many_symbolic_link_levels) return "is a loop of symbolic links";
  switch (st.type()) {
    case fs::file_type::regular: return "";
    case fs::file_type::not_found: return std::string(kNoSuchFile);
    case fs::file_type::directory: return "is a folder, not a regular file";
    case fs::file_type::fifo: return "is a FIFO, not a regular file";
    case fs::file_type::block:
    case fs::file_type::character: return "is a device, not a regular file";
    case fs::file_type::socket: return "is a socket, not a regular file";
    default: break;
  }
  return ec ? "cannot be examined (" + ec.message() + ")" : "is not a regular file";
}

std::string ThereButNotARegularFile(const fs::path& path) {
  std::string why = NotARegularFile(path);
  return why == kNoSuchFile ? std::string() : why;
}

std::string_view WithoutByteOrderMark(std::string_view line) {
  if (line.substr(0, 3) == "\xEF\xBB\xBF") line.remove_prefix(3);
  return line;
}

// The file's lines without their terminators (LF or CRLF) or a leading byte-order mark; trailing
// blank lines are dropped, a blank line before the last non-blank one is an error (it would shift
// every later frame).
std::vector<std::string> ReadLines(const fs::path& path) {
  if (const std::string why = ThereButNotARegularFile(path); !why.empty()) Fail(path, why);
  std::ifstream in(path);
  if (!in) Fail(path, "cannot open for reading");
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(std::move(line));
  if (in.bad()) Fail(path, "read error");
  if (!lines.empty()) lines.front() = std::string(WithoutByteOrderMark(lines.front()));
  while (!lines.empty() && Trim(lines.back()).empty()) lines.pop_back();
  if (lines.empty()) Fail(path, "file is empty (expected one frame per line)");
  for (std::size_t i = 0; i < lines.size(); ++i) {
    if (Trim(lines[i]).empty()) FailLine(path, i + 1, "empty line");
  }
  return lines;
}

// Parses one number; NaN and Inf are rejected here so no caller has to remember to.
double ParseNumber(const fs::path& path, std::size_t line, std::string_view token) {
  token = Trim(token);
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  double v = 0.0;
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), v);
  if (token.empty() || ec != std::errc() || end != token.data() + token.size()) {
    FailLine(path, line, "not a number: '" + Printable(token, 40) + "'");
  }
  if (!std::isfinite(v)) FailLine(path, line, "NaN or Inf: '" + Printable(token, 40) + "'");
  return v;
}

std::vector<std::string_view> SplitWhitespace(std::string_view s) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < s.size()) {
    while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
    const std::size_t start = i;
    while (i < s.size() && !std::isspace(static_cast<unsigned char>(s[i]))) ++i;
    if (i > start) out.push_back(s.substr(start, i - start));
  }
  return out;
}

std::vector<std::string_view> SplitCommas(std::string_view s) {
  std::vector<std::string_view> out;
  for (std::size_t start = 0;;) {
    const std::size_t comma = s.find(',', start);
    out.push_back(s.substr(start, comma == std::string_view::npos ? s.npos : comma - start));
    if (comma == std::string_view::npos) return out;
    start = comma + 1;
  }
}

}  // namespace dvpr::text_file
