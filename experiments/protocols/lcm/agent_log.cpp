#include "experiments/protocols/lcm/agent_log.h"

#include <charconv>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "experiments/results/result_writers.h"

namespace dvpr {

namespace {

std::string FloatText(float v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

template <typename T>
std::string Opt(const std::optional<T>& v) {
  return v ? std::to_string(*v) : std::string();
}

std::vector<std::string> SplitCsv(const std::string& line) {
  std::vector<std::string> out;
  std::string cell;
  std::istringstream in(line);
  while (std::getline(in, cell, ',')) out.push_back(cell);
  if (!line.empty() && line.back() == ',') out.emplace_back();
  return out;
}

// Reads the fields of one line in order, with the line named in errors.
class Fields {
 public:
  Fields(std::vector<std::string> cells, std::size_t expected, std::string where)
      : cells_(std::move(cells)), where_(std::move(where)) {
    if (cells_.size() != expected) {
      Fail("expected " + std::to_string(expected) + " fields, got " + std::to_string(cells_.size()));
    }
  }
  template <typename T>
  T Next() {
    const std::string& s = Take();
    T v{};
    const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
    if (r.ec != std::errc() || r.ptr != s.data() + s.size()) Fail("bad number '" + s + "'");
    return v;
  }
  template <typename T>
  std::optional<T> NextOptional() {
    if (cells_.at(pos_).empty()) {
      ++pos_;
      return std::nullopt;
    }
    return Next<T>();
  }
  std::string NextString() { return Take(); }
  [[noreturn]] void Fail(const std::string& what) const { throw std::runtime_error(where_ + ": " + what); }

 private:
  const std::string& Take() { return cells_.at(pos_++); }
  std::vector<std::string> cells_;
  std::string where_;
  std::size_t pos_ = 1;  // cell 0 is the record kind
};

void ReadQuery(Fields& f, AgentLog& log) {
  QueryRecord q;
  q.robot = RobotId(log.robot);
  q.frame = FrameId(f.Next<int>());
  q.sent = SimTime::Nanos(f.Next<std::int64_t>());
  q.expected_replies = f.Next<int>();
  q.received_replies = f.Next<int>();
  const auto match_robot = f.NextOptional<int>();
  const auto match_frame = f.NextOptional<int>();
  const auto distance = f.NextOptional<float>();
  if (match_robot.has_value() != match_frame.has_value() || match_frame.has_value() != distance.has_value()) {
    f.Fail("match_robot, match_frame and distance must be all given or all empty");
  }
  if (match_robot) q.best = IndexMatch{RobotId(*match_robot), FrameId(*match_frame), *distance};
  if (const auto latency = f.NextOptional<std::int64_t>()) q.latency = SimTime::Nanos(*latency);
  q.verify_requested = f.Next<int>() != 0;
  if (const auto accepted = f.NextOptional<int>()) q.verify_accepted = *accepted != 0;
  log.queries.push_back(q);
}

}  // namespace

void WriteAgentLog(const std::filesystem::path& path, const AgentLog& l) {
  std::ostringstream o;
  o << "# dvpr agent log, format 4 (experiments/protocols/lcm/agent_log.h)\n";
  o << "agent," << l.robot << ',' << l.robots << ',' << l.run << ',' << l.strategy << ',' << FormatDouble(l.speedup)
    << ',' << l.start_utime << ',' << l.end_ns << ',' << l.end_reason << ',' << l.published << ','
    << l.published_bytes << ',' << l.publish_failures << ',' << l.received << ',' << l.malformed << ','
    << l.foreign << ',' << l.medium_wire_bytes << ',' << l.datagrams << ',' << l.malformed_datagrams << ','
    << l.duplicates << ',' << l.incomplete_messages << ',' << l.kernel_dropped << ',' << l.out_of_range << ','
    << l.unauthenticated << ',' << l.held_dropped << ',' << l.held_bytes_peak << '\n';
  const RobotLoad& d = l.load;
  o << "load," << d.searches << ',' << d.remote_queries << ',' << d.comparisons << ',' << d.stored << ','
    << d.verifications << ',' << d.busy.ns() << ',' << d.max_queue << '\n';
  for (std::size_t r = 0; r < l.sent.size(); ++r) {
    const AgentLinkCount& s = l.sent[r];
    o << "sent," << r << ',' << s.messages << ',' << s.payload_bytes << ',' << s.wire_bytes << '\n';
  }
  for (std::size_t r = 0; r < l.received_from.size(); ++r) o << "recv," << r << ',' << l.received_from[r] << '\n';
  for (const QueryRecord& q : l.queries) {
    o << "query," << q.frame.value << ',' << q.sent.ns() << ',' << q.expected_replies << ',' << q.received_replies
      << ',' << (q.best ? std::to_string(q.best->robot.value) : "") << ','
      << (q.best ? std::to_string(q.best->frame.value) : "") << ',' << (q.best ? FloatText(q.best->distance) : "")
      << ',' << (q.latency ? std::to_string(q.latency->ns()) : "") << ',' << (q.verify_requested ? 1 : 0) << ','
      << Opt<int>(q.verify_accepted ? std::optional<int>(*q.verify_accepted) : std::nullopt) << '\n';
  }
  for (const LostRobot& r : l.lost) o << "lost," << r.robot.value << ',' << r.detected.ns() << '\n';
  WriteFileAtomic(path, o.str());
}

AgentLog ReadAgentLog(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path.string() + ": cannot read agent log");
  AgentLog l;
  bool have_agent = false;
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) {
    if (line.empty() || line[0] == '#') continue;
    const std::string where = path.string() + ":" + std::to_string(n);
    std::vector<std::string> cells = SplitCsv(line);
    const std::string kind = cells.at(0);
    if (kind == "agent") {
      Fields f(std::move(cells), 25, where);
      l.robot = f.Next<int>();
      l.robots = f.Next<int>();
      l.run = f.Next<int>();
      l.strategy = f.NextString();
      l.speedup = f.Next<double>();
      l.start_utime = f.Next<std::int64_t>();
      l.end_ns = f.Next<std::int64_t>();
      l.end_reason = f.NextString();
      l.published = f.Next<std::uint64_t>();
      l.published_bytes = f.Next<std::uint64_t>();
      l.publish_failures = f.Next<std::uint64_t>();
      l.received = f.Next<std::uint64_t>();
      l.malformed = f.Next<std::uint64_t>();
      l.foreign = f.Next<std::uint64_t>();
      l.medium_wire_bytes = f.Next<std::int64_t>();
      l.datagrams = f.Next<std::uint64_t>();
      l.malformed_datagrams = f.Next<std::uint64_t>();
      l.duplicates = f.Next<std::uint64_t>();
      l.incomplete_messages = f.Next<std::uint64_t>();
      l.kernel_dropped = f.Next<std::uint64_t>();
      l.out_of_range = f.Next<std::uint64_t>();
      l.unauthenticated = f.Next<std::uint64_t>();
      l.held_dropped = f.Next<std::uint64_t>();
      l.held_bytes_peak = f.Next<std::uint64_t>();
      have_agent = true;
    } else if (!have_agent) {
      throw std::runtime_error(where + ": the first record must be 'agent'");
    } else if (kind == "load") {
      Fields f(std::move(cells), 8, where);
      RobotLoad& d = l.load;
      d.searches = f.Next<std::int64_t>();
      d.remote_queries = f.Next<std::int64_t>();
      d.comparisons = f.Next<std::int64_t>();
      d.stored = f.Next<std::int64_t>();
      d.verifications = f.Next<std::int64_t>();
      d.busy = SimTime::Nanos(f.Next<std::int64_t>());
      d.max_queue = f.Next<std::int64_t>();
    } else if (kind == "sent") {
      Fields f(std::move(cells), 5, where);
      const auto dst = f.Next<std::size_t>();
      if (dst != l.sent.size()) f.Fail("sent lines must come in robot order");
      l.sent.push_back({f.Next<std::int64_t>(), f.Next<std::int64_t>(), f.Next<std::int64_t>()});
    } else if (kind == "recv") {
      Fields f(std::move(cells), 3, where);
      const auto src = f.Next<std::size_t>();
      if (src != l.received_from.size()) f.Fail("recv lines must come in robot order");
      l.received_from.push_back(f.Next<std::int64_t>());
    } else if (kind == "query") {
      Fields f(std::move(cells), 11, where);
      ReadQuery(f, l);
    } else if (kind == "lost") {
      Fields f(std::move(cells), 3, where);
      const RobotId robot(f.Next<int>());
      l.lost.push_back(LostRobot{robot, SimTime::Nanos(f.Next<std::int64_t>())});
    } else {
      throw std::runtime_error(where + ": unknown record '" + kind + "'");
    }
  }
  if (!have_agent) throw std::runtime_error(path.string() + ": no 'agent' record (not an agent log?)");
  if (l.sent.size() != static_cast<std::size_t>(l.robots) || l.received_from.size() != static_cast<std::size_t>(l.robots)) {
    throw std::runtime_error(path.string() + ": expected one sent and one recv line per robot");
  }
  return l;
}

}  // namespace dvpr
