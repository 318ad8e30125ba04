#include "experiments/replay/replay_page.h"

#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <tuple>
#include <utility>
#include <vector>

#include "experiments/results/result_writers.h"

namespace dvpr::replay {

namespace {

// The code point of the valid UTF-8 sequence at s[i] and its length, or length 0 when the bytes
// there are not one (a stray or cut sequence, an overlong form, a surrogate, above U+10FFFF).
std::pair<char32_t, std::size_t> DecodeUtf8(std::string_view s, std::size_t i) {
  const auto b = [&](std::size_t k) { return static_cast<unsigned char>(s[i + k]); };
  const unsigned char c = b(0);
  std::size_t n = 0;
  char32_t cp = 0;
  if (c >= 0xc2 && c <= 0xdf) {
    n = 2;
    cp = c & 0x1f;
  } else if (c >= 0xe0 && c <= 0xef) {
    n = 3;
    cp = c & 0x0f;
  } else if (c >= 0xf0 && c <= 0xf4) {
    n = 4;
    cp = c & 0x07;
  } else {
    return {0, 0};
  }
  if (i + n > s.size()) return {0, 0};
  for (std::size_t k = 1; k < n; ++k) {
    if ((b(k) & 0xc0) != 0x80) return {0, 0};
    cp = (cp << 6) | (b(k) & 0x3f);
  }
  constexpr char32_t kSmallest[5] = {0, 0, 0x80, 0x800, 0x10000};
  if (cp < kSmallest[n] || cp > 0x10ffff || (cp >= 0xd800 && cp <= 0xdfff)) return {0, 0};
  return {cp, n};
}

void AppendEscape(std::string& out, unsigned value) {
  char buf[16];  // \uXXXX; room for 8 digits, as the compiler cannot see that value <= 0xffff
  std::snprintf(buf, sizeof buf, "\\u%04x", value);
  out += buf;
}

// A JSON string that is plain ASCII and safe inside the page's <script> element: quotes and
// backslashes escaped, and as \uXXXX every control character, '<', '>' and '&' (so no
// "</script>" or "<!--" can end or change the element) and every non-ASCII character (so
// U+2028 and U+2029, line ends to older JavaScript, never appear raw). Bytes that are not valid
// UTF-8 become U+FFFD, the replacement character.
std::string JsonString(std::string_view s) {
  std::string out = "\"";
  for (std::size_t i = 0; i < s.size();) {
    const char c = s[i];
    const auto u = static_cast<unsigned char>(c);
    if (u < 0x80) {
      if (c == '"' || c == '\\') {
        out += '\\';
        out += c;
      } else if (u < 0x20 || u == 0x7f || c == '<' || c == '>' || c == '&') {
        AppendEscape(out, u);
      } else {
        out += c;
      }
      ++i;
      continue;
    }
    const auto [cp, n] = DecodeUtf8(s, i);
    if (n == 0) {
      AppendEscape(out, 0xfffd);
      ++i;
    } else if (cp >= 0x10000) {  // a UTF-16 surrogate pair
      AppendEscape(out, 0xd800 + ((cp - 0x10000) >> 10));
      AppendEscape(out, 0xdc00 + ((cp - 0x10000) & 0x3ff));
      i += n;
    } else {
      AppendEscape(out, cp);
      i += n;
    }
  }
  return out + "\"";
}

std::int64_t Micros(std::int64_t ns) { return (ns + 500) / 1000; }

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

// One strategy's messages: the kinds table, then five integers per message; on a radio each
// message's hops too ("h").
void WriteMessages(std::ostream& o, const StrategyMessages& s, bool with_hops) {
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
  o << "],\"m\":[" << m.str() << ']';
  if (with_hops) {
    o << ",\"h\":[";
    for (std::size_t i = 0; i < s.messages.size(); ++i) o << (i ? "," : "") << s.messages[i].hops;
    o << ']';
  }
  o << '}';
}

}  // namespace

std::string PageData(const ReplayRun& run, const Tracks& tracks) {
  std::ostringstream o;
  o << "{\"name\":" << JsonString(tracks.name) << ",\"robots\":" << run.robots << ",\"run\":" << run.run
    << ",\"variant\":" << run.network_variant << ",\"network\":" << JsonString(NetworkName(run.network, NameStyle::kPage))
    << ",\"fps\":" << FormatDouble(tracks.fps);
  if (!std::isnan(run.network.range_m)) o << ",\"range_m\":" << FormatDouble(run.network.range_m);
  o << ",\"roles\":[";
  for (int r = 0; r < kMessageRoles; ++r) o << (r ? "," : "") << JsonString(RoleName(static_cast<MessageRole>(r)));
  o << "],";
  WriteTracks(o, tracks);
  o << ",\"strategies\":[";
  for (std::size_t s = 0; s < run.strategies.size(); ++s) {
    if (s) o << ',';
    WriteMessages(o, run.strategies[s], run.network.model == "radio");
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
