// network.schedule's file (talk_schedule.h).
#include "experiments/config/talk_schedule.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>

#include "experiments/domain/data/printable.h"
#include "experiments/domain/data/text_file.h"

namespace dvpr {

namespace {

constexpr double kMaxSeconds = 360'000'000.0;  // 100 000 h: Dropout::kMaxAt

std::string Lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

std::string Trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

std::vector<std::string> Fields(const std::string& line) {
  std::vector<std::string> out;
  std::string f;
  std::istringstream in(line);
  while (std::getline(in, f, ',')) out.push_back(Trim(f));
  if (!line.empty() && line.back() == ',') out.emplace_back();
  return out;
}

struct Located {
  ScheduledWindow w;
  int line = 0;
};

// Sets `col` to header column i; a column named twice (robot and ROBOT_ID, start_s and START_S)
// is refused, as either could be meant.
void SetColumn(std::optional<std::size_t>& col, std::size_t i, const std::vector<std::string>& header,
               const std::string& where) {
  if (col) {
    throw std::invalid_argument(where + "the header names both '" + Printable(header[*col]) + "' (column " +
                                std::to_string(*col + 1) + ") and '" + Printable(header[i]) + "' (column " +
                                std::to_string(i + 1) + "); keep one");
  }
  col = i;
}

}  // namespace

std::vector<ScheduledWindow> ReadTalkSchedule(const std::filesystem::path& path, int largest_robot) {
  const std::string file = path.string();
  // By stat, before opening: a FIFO would wait for a writer.
  if (const std::string why = text_file::ThereButNotARegularFile(path); !why.empty()) {
    throw std::invalid_argument(file + ": " + why);
  }
  std::ifstream in(path);
  if (!in) throw std::invalid_argument(file + ": cannot be read");
  auto fail = [&file](int line, const std::string& problem) -> void {
    throw std::invalid_argument(file + ": line " + std::to_string(line) + ": " + problem);
  };
  std::string text;
  int line = 0;
  std::optional<std::size_t> robot_col, start_col, end_col;
  std::size_t columns = 0;
  while (std::getline(in, text)) {
    ++line;
    if (line == 1) text = std::string(text_file::WithoutByteOrderMark(text));
    if (Trim(text).empty()) continue;
    const std::vector<std::string> header = Fields(text);
    columns = header.size();
    const std::string where = file + ": line " + std::to_string(line) + ": ";
    for (std::size_t i = 0; i < header.size(); ++i) {
      const std::string h = Lower(header[i]);
      if (h == "robot" || h == "robot_id") SetColumn(robot_col, i, header, where);
      if (h == "start_s") SetColumn(start_col, i, header, where);
      if (h == "end_s") SetColumn(end_col, i, header, where);
    }
    if (!robot_col || !start_col || !end_col) {
      fail(line, "expected a header naming the columns robot, start_s and end_s (or ROBOT_ID, START_S, END_S), got '" +
                     Printable(Trim(text)) + "'");
    }
    break;
  }
  if (!robot_col) throw std::invalid_argument(file + ": expected a header robot,start_s,end_s and windows, got an empty file");
  std::vector<Located> windows;
  while (std::getline(in, text)) {
    ++line;
    if (Trim(text).empty()) continue;
    const std::vector<std::string> f = Fields(text);
    if (f.size() != columns) {
      fail(line, "expected " + std::to_string(columns) + " comma-separated fields as the header, got " +
                     std::to_string(f.size()));
    }
    int robot = -1;
    const std::string& r = f[*robot_col];
    const auto [rend, rec] = std::from_chars(r.data(), r.data() + r.size(), robot);
    if (rec != std::errc() || rend != r.data() + r.size() || robot < 0 || robot > 32767) {
      fail(line, "robot: expected an integer in [0, 32767], got '" + Printable(r) + "'");
    }
    if (robot > largest_robot) {
      fail(line, "robot " + std::to_string(robot) + " is in no team of the sweep (its largest robot id is " +
                     std::to_string(largest_robot) + ")");
    }
    auto seconds = [&](std::size_t col, const char* name) {
      const std::string& s = f[col];
      double v = 0;
      const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
      if (ec != std::errc() || end != s.data() + s.size() || s.empty() || !std::isfinite(v) || v < 0 || v > kMaxSeconds) {
        fail(line, std::string(name) + ": expected seconds in [0, 360000000], got '" + Printable(s) + "'");
      }
      return SimTime::Nanos(std::llround(v * 1e9));
    };
    const SimTime from = seconds(*start_col, "start_s");
    const SimTime until = seconds(*end_col, "end_s");
    if (!(from < until)) fail(line, "end_s must be after start_s");
    windows.push_back(Located{ScheduledWindow{robot, TalkWindow{from, until}}, line});
  }
  if (windows.empty()) throw std::invalid_argument(file + ": expected at least one window after the header");
  std::stable_sort(windows.begin(), windows.end(), [](const Located& a, const Located& b) {
    return a.w.robot != b.w.robot ? a.w.robot < b.w.robot : a.w.window.from < b.w.window.from;
  });
  std::vector<ScheduledWindow> out;
  for (std::size_t i = 0; i < windows.size(); ++i) {
    if (i > 0 && windows[i].w.robot == windows[i - 1].w.robot && windows[i].w.window.from < windows[i - 1].w.window.until) {
      const int a = std::min(windows[i].line, windows[i - 1].line), b = std::max(windows[i].line, windows[i - 1].line);
      throw std::invalid_argument(file + ": lines " + std::to_string(a) + " and " + std::to_string(b) + ": robot " +
                                  std::to_string(windows[i].w.robot) + "'s windows overlap");
    }
    out.push_back(windows[i].w);
  }
  return out;
}

}  // namespace dvpr
