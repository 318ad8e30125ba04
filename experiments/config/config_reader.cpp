#include <algorithm>
#include "experiments/config/config_reader.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <system_error>

#include "experiments/domain/data/text_file.h"
#include "net_models/core/param_checks.h"

namespace dvpr::config_detail {

namespace {

std::string Quoted(const std::string& s) { return "'" + s + "'"; }

std::string KindOf(const YAML::Node& node) {
  if (!node.IsDefined()) return "nothing";  // a missing key: Type() would throw YAML::InvalidNode
  switch (node.Type()) {
    case YAML::NodeType::Map: return "a map";
    case YAML::NodeType::Sequence: return "a list";
    case YAML::NodeType::Scalar: return Quoted(node.Scalar());
    default: return "nothing";
  }
}

}  // namespace

void Field::Fail(const std::string& problem) const {
  throw ConfigError(origin_->name + ": " + (path_.empty() ? "(top level)" : path_) + ": " +
                    problem);
}

void Field::ExpectMap(std::initializer_list<std::string_view> allowed) const {
  if (!node_.IsDefined() || !node_.IsMap()) Fail("expected a map, got " + KindOf(node_));
  for (const auto& entry : node_) {
    const std::string key = entry.first.Scalar();
    bool known = false;
    for (std::string_view a : allowed) known = known || a == key;
    if (known) continue;
    std::string list;
    for (std::string_view a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
    Child(key).Fail("unknown key (expected one of: " + list + ")");
  }
}

void Field::FailWithin(const std::string& field_and_problem) const {
  throw ConfigError(origin_->name + ": " + (path_.empty() ? "" : path_ + ".") + field_and_problem);
}

Field Field::Child(std::string_view key) const {
  const std::string k(key);
  Field child(*origin_, node_.IsMap() ? node_[k] : YAML::Node(YAML::NodeType::Undefined),
              path_.empty() ? k : path_ + "." + k);
  // `runs:` with nothing after it is more likely a forgotten value than a wish for the default.
  if (child.node_.IsDefined() && child.node_.IsNull()) {
    child.Fail("no value given (write one, or leave the key out for its default)");
  }
  return child;
}

std::vector<Field> Field::Items() const {
  if (node_.IsMap()) Fail("expected a value or a list of values, got a map");
  if (!node_.IsSequence()) return {*this};
  if (node_.size() == 0) Fail("expected at least one value, got an empty list");
  std::vector<Field> items;
  for (std::size_t i = 0; i < node_.size(); ++i) {
    items.emplace_back(*origin_, node_[i], path_ + "[" + std::to_string(i) + "]");
  }
  return items;
}

const std::string& Field::Scalar(std::string_view expected) const {
  // IsDefined first: a missing key (robots: {from: 2}) is an invalid node whose IsScalar() throws
  // YAML::InvalidNode instead of a ConfigError naming the key (found by fuzz_config).
  if (!node_.IsDefined() || !node_.IsScalar()) {
    Fail("expected " + std::string(expected) + ", got " + KindOf(node_));
  }
  return node_.Scalar();
}

std::string Field::String() const { return Scalar("a string"); }

void Field::FailRange(const std::string& min, const std::string& max) const {
  Fail(RangeProblem(min, max, node_.Scalar()));
}

long long Field::Int(long long min, long long max) const {
  const std::string& s = Scalar("an integer");
  long long v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  const bool whole = end == s.data() + s.size() && !s.empty();
  if (ec == std::errc::result_out_of_range && whole) FailRange(std::to_string(min), std::to_string(max));
  if (ec != std::errc() || !whole) Fail("expected an integer, got " + Quoted(s));
  if (v < min || v > max) FailRange(std::to_string(min), std::to_string(max));
  return v;
}

double Field::Double() const {
  const std::string& s = Scalar("a number");
  double v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size() || !std::isfinite(v)) {
    Fail("expected a number, got " + Quoted(s));
  }
  return v;
}

double Field::Double(double min, double max) const {
  const std::string& s = Scalar("a number");
  double v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  const bool whole = end == s.data() + s.size() && !s.empty();
  // from_chars reports 1e400 and 1e-400 as out of range: both lie outside any range here.
  if (ec == std::errc::result_out_of_range && whole) FailRange(FormatNumber(min), FormatNumber(max));
  if (ec != std::errc() || !whole || std::isnan(v)) Fail("expected a number, got " + Quoted(s));
  if (!(v >= min && v <= max)) FailRange(FormatNumber(min), FormatNumber(max));
  return v;
}

bool Field::Bool() const {
  const std::string& s = Scalar("true or false");
  if (s == "true") return true;
  if (s == "false") return false;
  Fail("expected true or false, got " + Quoted(s));
}

DataRate Field::Rate(DataRate min, DataRate max) const {
  const std::string& s = Scalar("a data rate with a unit, e.g. 10Mbps");
  DataRate r;
  try {
    r = ParseDataRate(s);
  } catch (const QuantityTooLarge&) {
    FailRange(ToString(min), ToString(max));
  } catch (const std::invalid_argument& e) {
    Fail(std::string("expected a data rate with a unit, e.g. 10Mbps (") + e.what() + ")");
  }
  if (r < min || r > max) FailRange(ToString(min), ToString(max));
  return r;
}

SimTime Field::Duration(SimTime min, SimTime max) const {
  const std::string& s = Scalar("a duration with a unit, e.g. 5ms");
  SimTime t;
  try {
    t = ParseDuration(s);
  } catch (const QuantityTooLarge&) {
    FailRange(FormatDuration(min), FormatDuration(max));
  } catch (const std::invalid_argument& e) {
    Fail(std::string("expected a duration with a unit, e.g. 5ms (") + e.what() + ")");
  }
  if (t.ns() == 0 && min.ns() > 0 && NonZeroNumber(s)) {
    Fail(s + " rounds to 0 at the resolution of durations (1ns), below the smallest allowed value " +
         FormatDuration(min));
  }
  if (t < min || t > max) FailRange(FormatDuration(min), FormatDuration(max));
  return t;
}

Bytes Field::Size(Bytes min, Bytes max, bool plain_integer_is_bytes) const {
  const std::string& s = Scalar("a size with a unit, e.g. 25kB");
  if (plain_integer_is_bytes && !s.empty() &&
      s.find_first_not_of("0123456789") == std::string::npos) {
    std::int64_t n = 0;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), n);
    if (ec != std::errc() || n < min.value() || n > max.value()) FailRange(ToString(min), ToString(max));
    return Bytes(n);
  }
  Bytes b;
  try {
    b = ParseBytes(s);
  } catch (const QuantityTooLarge&) {
    FailRange(ToString(min), ToString(max));
  } catch (const std::invalid_argument& e) {
    Fail(std::string("expected a size with a unit, e.g. 25kB (") + e.what() + ")");
  }
  if (b < min || b > max) FailRange(ToString(min), ToString(max));
  return b;
}

std::size_t Field::Choice(const std::vector<std::string>& names) const {
  const std::string& s = Scalar("a name");
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (names[i] == s) return i;
  }
  std::string list;
  for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
  Fail("unknown value " + Quoted(s) + " (expected one of: " + list + ")");
}

std::vector<std::filesystem::path> SearchDirs(const Origin& origin) {
  std::vector<std::filesystem::path> dirs{origin.base_dir};
  std::error_code ec;
  const auto cwd = std::filesystem::current_path(ec);
  if (!ec) dirs.push_back(cwd);
  dirs.emplace_back(DVPR_SOURCE_TREE);
  return dirs;
}

bool NonZeroNumber(std::string_view quantity) {
  for (const char c : quantity) {
    if (c >= '1' && c <= '9') return true;
    if (c != '0' && c != '.' && c != '+' && c != ' ' && c != '\t') return false;
  }
  return false;
}

std::filesystem::path Field::ExistingFile() const {
  const std::filesystem::path p = String();
  if (p.empty()) Fail("expected a file path, got an empty string");
  std::vector<std::filesystem::path> tried;
  if (p.is_absolute()) {
    tried.push_back(p);
  } else {
    for (const auto& dir : SearchDirs(*origin_)) tried.push_back(dir / p);
  }
  if (origin_->files == ConfigFiles::kNamesOnly) {
    const auto found = std::find_if(tried.begin(), tried.end(), [](const std::filesystem::path& candidate) {
      return text_file::NotARegularFile(candidate).empty();
    });
    return std::filesystem::absolute(found == tried.end() ? tried.front() : *found).lexically_normal();
  }
  for (const auto& candidate : tried) {
    const std::string why = text_file::NotARegularFile(candidate);
    if (why.empty()) return std::filesystem::absolute(candidate).lexically_normal();
    // Something is there: "not found" would mislead.
    if (why != text_file::kNoSuchFile) Fail(Quoted(candidate.string()) + " " + why);
  }
  std::ostringstream where;
  for (std::size_t i = 0; i < tried.size(); ++i) where << (i ? ", " : "") << tried[i].string();
  Fail("file not found: " + Quoted(p.string()) + " (looked for " + where.str() + ")");
}

}  // namespace dvpr::config_detail
