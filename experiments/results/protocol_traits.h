#pragma once
// What the code asks of a protocol, answered once per protocol. A protocol is a name in a
// config's `protocols:` list and in runs.csv's protocol column; everything else the sweep, its
// checks, the figures and the replay need to know about it is one of its traits here, so no code
// outside config parsing and the protocol registry (experiments/sweep/builtin_protocols.cpp)
// compares a protocol's name. A new protocol adds its entry to the catalogue
// (protocol_traits.cpp) and its row filler uses its name constant below.
//
// It lives in results/ because the lowest layers that ask are the figures and the replay, which
// read runs.csv rows and know no protocol's code.
#include <string_view>
#include <vector>

namespace dvpr {

// The protocols' names, as the config, runs.csv and the registry spell them.
inline constexpr std::string_view kPaperProtocol = "paper";  // static evaluation (protocols/paper)
inline constexpr std::string_view kSimProtocol = "sim";      // virtual-time simulation (protocols/sim)
inline constexpr std::string_view kLcmProtocol = "lcm";      // real agent processes (dvpr launch)

struct ProtocolTraits {
  std::string_view name;
  // How the figures' titles name its rows: "paper (static) protocol", "simulation".
  std::string_view title;
  // Ranks every deployment frame against the whole deployment at once, without time or a
  // network (the paper's own evaluation): exact accuracy, so the accuracy figures and the BoW
  // comparison take its rows first; it holds the windowed neighbour lists of every frame.
  bool static_evaluation = false;
  // Runs on the sweep's simulated network: one run (and row) per network variant of the config's
  // network section, which it validates; failover timing and bytes by message role are measured
  // on it; its messages.csv is what `dvpr replay` shows.
  bool simulated_network = false;
  // Its robots exchange messages, so what only the wire limits (int16 lengths, descriptor sizes)
  // is checked for a sweep that runs it.
  bool sends_messages = false;
  // Runs the bag-of-words (bow_) strategies (docs/bow.md).
  bool bow_strategies = false;
  // The strategy whose AUC divides a row's AUC into its relative AUC.
  std::string_view relative_auc_reference;
};

// Every protocol this dvpr knows, each once.
const std::vector<ProtocolTraits>& ProtocolCatalogue();

// The traits of `name`, a protocol the config's parser has accepted or the registry holds;
// std::invalid_argument naming it and the known protocols when there is no such protocol.
const ProtocolTraits& TraitsOf(std::string_view name);

// The traits of the protocol a result row names, read from a file: a protocol this dvpr does not
// know has every trait false (its rows are in no figure and no replay), never an error.
const ProtocolTraits& RowTraits(std::string_view name);

// Whether any of `names` (known protocols, as TraitsOf) has `trait`, e.g.
// AnyProtocol(config.sweep.protocols, &ProtocolTraits::simulated_network).
template <typename Names>
bool AnyProtocol(const Names& names, bool ProtocolTraits::*trait) {
  for (const auto& name : names) {
    if (TraitsOf(name).*trait) return true;
  }
  return false;
}

}  // namespace dvpr
