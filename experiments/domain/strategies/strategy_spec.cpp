#include "experiments/domain/strategies/strategy_spec.h"

#include <array>
#include <charconv>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace dvpr {

namespace {

using Spec = StrategySpec;
using Fields = std::vector<std::string_view>;

std::string Quoted(std::string_view s) { return "'" + std::string(s) + "'"; }

// A whole number >= 1 written as `tag` then its digits ("c10"), or bare when tag is 0 ("2").
int Whole(std::string_view field, char tag, const std::string& what) {
  const std::string written = tag ? std::string(1, tag) + what : what;
  if (tag && (field.empty() || field.front() != tag)) {
    throw std::invalid_argument("expected " + written + ", got " + Quoted(field));
  }
  const std::string_view digits = tag ? field.substr(1) : field;
  int v = 0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), v);
  if (ec != std::errc() || end != digits.data() + digits.size() || v < 1) {
    throw std::invalid_argument(what + " must be a whole number >= 1, got " + Quoted(field));
  }
  if (std::to_string(v) != digits) {
    throw std::invalid_argument(what + " must be written " + (tag ? std::string(1, tag) : "") + std::to_string(v));
  }
  return v;
}

// A finite number >= 0 in its shortest spelling ("0.1").
double Number(std::string_view field, const std::string& what) {
  double v = 0;
  const auto [end, ec] = std::from_chars(field.data(), field.data() + field.size(), v);
  if (ec != std::errc() || end != field.data() + field.size() || !std::isfinite(v) || v < 0) {
    throw std::invalid_argument(what + " must be a number >= 0, got " + Quoted(field));
  }
  std::array<char, 32> buf{};
  const auto shortest = std::to_chars(buf.data(), buf.data() + buf.size(), v);
  const std::string_view canonical(buf.data(), static_cast<std::size_t>(shortest.ptr - buf.data()));
  if (canonical != field) {
    throw std::invalid_argument(what + " must be written " + std::string(canonical) + ", not " + Quoted(field));
  }
  return v;
}

Fields Split(std::string_view s) {
  Fields out;
  for (std::size_t at = 0;;) {
    const std::size_t next = s.find('_', at);
    out.push_back(s.substr(at, next == std::string_view::npos ? std::string_view::npos : next - at));
    if (next == std::string_view::npos) return out;
    at = next + 1;
  }
}

// Each family reads the fields after its prefix into the spec; false: the fields have another
// shape than the family's form.
struct Family {
  std::string_view prefix;
  std::string_view form;
  bool (*read)(const Fields& f, Spec& s);
};

bool ReadTable(const Fields& f, Spec& s, Spec::Table table) {
  if (f.size() != 1) return false;
  s.table = table;
  s.clusters_per_robot = Whole(f[0], 'c', "C");
  return true;
}

constexpr std::array kRoutings = {
    Family{"multi_probe_", "multi_probe_M",
           [](const Fields& f, Spec& s) {
             if (f.size() != 1) return false;
             s.placement = Spec::Placement::kProbe;
             s.probe = {.probes = Whole(f[0], 0, "M"), .epsilon = -1};
             return true;
           }},
    Family{"adaptive_probe_", "adaptive_probe_E",
           [](const Fields& f, Spec& s) {
             if (f.size() != 1) return false;
             s.placement = Spec::Placement::kProbe;
             s.probe = {.probes = kAdaptiveProbes, .epsilon = Number(f[0], "E")};
             return true;
           }},
    Family{"replicate_", "replicate_E[_rR]",
           [](const Fields& f, Spec& s) {
             if (f.empty() || f.size() > 2) return false;
             s.placement = Spec::Placement::kReplicate;
             s.replicate = {.epsilon = Number(f[0], "E"),
                            .max_replicas = f.size() == 2 ? Whole(f[1], 'r', "R") : kDefaultReplicas};
             return true;
           }},
};

// balanced_sample_ before balanced_: the first prefix that matches decides.
constexpr std::array kTables = {
    Family{"lpt_", "lpt_cC[_train]",
           [](const Fields& f, Spec& s) {
             if (f.size() > 2 || (f.size() == 2 && f[1] != "train")) return false;
             s.loads_from_training = f.size() == 2;
             return ReadTable(Fields(f.begin(), f.begin() + 1), s, Spec::Table::kLpt);
           }},
    Family{"bounded_", "bounded_cC_B",
           [](const Fields& f, Spec& s) {
             if (f.size() != 2) return false;
             s.balance.epsilon = Number(f[1], "B");
             return ReadTable(Fields(f.begin(), f.begin() + 1), s, Spec::Table::kBounded);
           }},
    Family{"sample_", "sample_cC", [](const Fields& f, Spec& s) { return ReadTable(f, s, Spec::Table::kSampleKMeans); }},
    Family{"balanced_sample_", "balanced_sample_cC",
           [](const Fields& f, Spec& s) { return ReadTable(f, s, Spec::Table::kBalancedSample); }},
    Family{"balanced_", "balanced_cC", [](const Fields& f, Spec& s) { return ReadTable(f, s, Spec::Table::kBalanced); }},
};

// Re-clustering starts from lpt_cC_train's table (no deployment knowledge) and combines with no
// routing: the agents route by their current table.
constexpr Family kRecluster{"recluster_", "recluster_cC_pP", [](const Fields& f, Spec& s) {
  if (f.size() != 2) return false;
  s.table = Spec::Table::kLpt;
  s.loads_from_training = true;
  s.clusters_per_robot = Whole(f[0], 'c', "C");
  s.recluster_period = Whole(f[1], 'p', "P");
  return true;
}};

template <typename Families>
std::string Forms(const Families& families) {
  std::string list;
  for (const Family& f : families) list += (list.empty() ? "" : ", ") + std::string(f.form);
  return list;
}

// Reads `part` with the family whose prefix it starts with; false when none does.
template <typename Families>
bool ReadPart(std::string_view part, const Families& families, Spec& s) {
  for (const Family& family : families) {
    if (!part.starts_with(family.prefix) || part.size() == family.prefix.size()) continue;
    if (!family.read(Split(part.substr(family.prefix.size())), s)) {
      throw std::invalid_argument("expected the form " + std::string(family.form));
    }
    return true;
  }
  return false;
}

Spec ParseParts(std::string_view name) {
  Spec s;
  s.name = std::string(name);
  if (name == "decentralized") return s;
  if (name == "broadcast") {
    s.placement = Spec::Placement::kBroadcast;
    return s;
  }
  for (const auto& [bow_name, kind] : {std::pair{"bow_centralized", Spec::Bow::kCentralized},
                                       std::pair{"bow_broadcast", Spec::Bow::kBroadcast},
                                       std::pair{"bow_decentralized", Spec::Bow::kModulo},
                                       std::pair{"bow_decentralized_df", Spec::Bow::kDocumentFrequency}}) {
    if (name == bow_name) {
      s.bow = kind;
      return s;
    }
  }
  const std::size_t plus = name.find('+');
  if (plus == std::string_view::npos) {
    if (ReadPart(name, kRoutings, s) || ReadPart(name, kTables, s) ||
        ReadPart(name, std::array{kRecluster}, s)) {
      return s;
    }
    throw std::invalid_argument("unknown name (expected decentralized, broadcast, " + Forms(kRoutings) + ", " +
                                Forms(kTables) + ", " + std::string(kRecluster.form) +
                                ", bow_centralized, bow_broadcast, bow_decentralized, bow_decentralized_df or TABLE+ROUTING)");
  }
  if (name.find('+', plus + 1) != std::string_view::npos) {
    throw std::invalid_argument("at most one '+' (TABLE+ROUTING)");
  }
  if (!ReadPart(name.substr(0, plus), kTables, s)) {
    throw std::invalid_argument("before '+' comes a table (" + Forms(kTables) + ")");
  }
  if (!ReadPart(name.substr(plus + 1), kRoutings, s)) {
    throw std::invalid_argument("after '+' comes a routing (" + Forms(kRoutings) + ")");
  }
  return s;
}

}  // namespace

StrategySpec ParseStrategy(std::string_view name) {
  try {
    return ParseParts(name);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(Quoted(name) + " is not a strategy: " + e.what());
  }
}

}  // namespace dvpr
