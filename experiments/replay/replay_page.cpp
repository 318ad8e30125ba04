#include "experiments/replay/replay_page.h"

#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <tuple>
#include <vector>

#include "experiments/results/result_writers.h"

namespace dvpr::replay {

namespace {

std::string JsonString(std::string_view s) {
  std::string out = "\"";
  for (const char c : s) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (u < 0x20 || c == '<' || c == '>' || c == '&' || u >= 0x80) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", u);  // bytes >= 0x80 shown as Latin-1: names are ASCII
      out += buf;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

std::int64_t Micros(std::int64_t ns) { return (ns + 500) / 1000; }

std::string Rate(double bps) {
  if (bps >= 1e9) return FormatDouble(bps / 1e9) + " Gbit/s";
  if (bps >= 1e6) return FormatDouble(bps / 1e6) + " Mbit/s";
  if (bps >= 1e3) return FormatDouble(bps / 1e3) + " kbit/s";
  return FormatDouble(bps) + " bit/s";
}

void WriteTracks(std::ostream& o, const Tracks& tracks) {
  o << "\"first\":[";
  for (std::size_t r = 0; r < tracks.robots.size(); ++r) o << (r ? "," : "") << tracks.robots[r].first_frame;
  o << "],\"tracks\":[";
  for (std::size_t r = 0; r < tracks.robots.size(); ++r) {
    const RobotTrack& t = tracks.robots[r];
    o << (r ? ",[" : "[");
    for (std::size_t k = 0; k < t.x.size(); ++k) {
      o << (k ? "," : "") << std::llround(t.x[k] * 10) << ',' << std::llround(t.z[k] * 10);
    }
    o << ']';
  }
  o << ']';
}

// One strategy's messages: the kinds table, then five integers per message.
void WriteMessages(std::ostream& o, const StrategyMessages& s) {
  std::map<std::tuple<int, std::int64_t, int>, int> kinds;
  std::ostringstream m;
  std::int64_t previous_us = 0;
  for (std::size_t i = 0; i < s.messages.size(); ++i) {
    const Message& msg = s.messages[i];
    const auto key = std::make_tuple(static_cast<int>(msg.role), msg.counted_bytes, static_cast<int>(msg.queue));
    const int kind = kinds.try_emplace(key, static_cast<int>(kinds.size())).first->second;
    const std::int64_t sent_us = Micros(msg.sent_ns);
    const std::int64_t latency_us = msg.delivered_ns >= 0 ? Micros(msg.delivered_ns) - sent_us : msg.dropped ? -1 : -2;
    m << (i ? "," : "") << sent_us - previous_us << ',' << latency_us << ',' << msg.src << ',' << msg.dst << ',' << kind;
    previous_us = sent_us;
  }
  std::vector<std::tuple<int, std::int64_t, int>> table(kinds.size());
  for (const auto& [key, index] : kinds) table[static_cast<std::size_t>(index)] = key;
  o << "{\"name\":" << JsonString(s.strategy) << ",\"kinds\":[";
  for (std::size_t k = 0; k < table.size(); ++k) {
    o << (k ? ",[" : "[") << std::get<0>(table[k]) << ',' << std::get<1>(table[k]) << ',' << std::get<2>(table[k]) << ']';
  }
  o << "],\"m\":[" << m.str() << "]}";
}

}  // namespace

std::string NetworkName(const ReplayRun& run) {
  std::string model = run.network_model;
  if (model == "point_to_point") model = "point-to-point";
  if (model == "shared_medium") model = "shared medium";
  std::string name = model + ", " + Rate(run.bandwidth_bps) + ", " + FormatDouble(run.latency_ms) + " ms";
  if (!run.loss.empty() && run.loss != "none") name += ", loss: " + run.loss;
  return name;
}

std::string PageData(const ReplayRun& run, const Tracks& tracks) {
  std::ostringstream o;
  o << "{\"name\":" << JsonString(tracks.name) << ",\"robots\":" << run.robots << ",\"run\":" << run.run
    << ",\"variant\":" << run.network_variant << ",\"network\":" << JsonString(NetworkName(run))
    << ",\"fps\":" << FormatDouble(tracks.fps) << ",\"roles\":[";
  for (int r = 0; r < kMessageRoles; ++r) o << (r ? "," : "") << JsonString(RoleName(static_cast<MessageRole>(r)));
  o << "],";
  WriteTracks(o, tracks);
  o << ",\"strategies\":[";
  for (std::size_t s = 0; s < run.strategies.size(); ++s) {
    if (s) o << ',';
    WriteMessages(o, run.strategies[s]);
  }
  o << "]}";
  return o.str();
}

std::string ReplayPage(const ReplayRun& run, const Tracks& tracks) {
  std::string page = kPageTemplate;
  const std::size_t at = page.find(kDataPlaceholder);
  if (at == std::string::npos) throw std::logic_error("replay page template without its data placeholder");
  page.replace(at, std::string_view(kDataPlaceholder).size(), PageData(run, tracks));
  return page;
}

}  // namespace dvpr::replay
