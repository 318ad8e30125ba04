#include "experiments/results/protocol_traits.h"

#include <stdexcept>
#include <string>

namespace dvpr {

const std::vector<ProtocolTraits>& ProtocolCatalogue() {
  static const std::vector<ProtocolTraits> catalogue{
      {.name = kPaperProtocol,
       .title = "paper (static) protocol",
       .static_evaluation = true,
       .simulated_network = false,
       .sends_messages = false,
       .bow_strategies = true,
       // Broadcast ranks every query against every other robot's frames: the centralized ranking.
       .relative_auc_reference = "centralized"},
      {.name = kSimProtocol,
       .title = "simulation",
       .static_evaluation = false,
       .simulated_network = true,
       .sends_messages = true,
       .bow_strategies = true,
       .relative_auc_reference = "broadcast"},
      {.name = kLcmProtocol,
       .title = "LCM agent processes",
       .static_evaluation = false,
       .simulated_network = false,  // a real network, which no config describes
       .sends_messages = true,
       .bow_strategies = false,
       .relative_auc_reference = "broadcast"},
  };
  return catalogue;
}

namespace {

const ProtocolTraits* Find(std::string_view name) {
  for (const ProtocolTraits& t : ProtocolCatalogue()) {
    if (t.name == name) return &t;
  }
  return nullptr;
}

}  // namespace

const ProtocolTraits& TraitsOf(std::string_view name) {
  if (const ProtocolTraits* t = Find(name)) return *t;
  std::string known;
  for (const ProtocolTraits& t : ProtocolCatalogue()) known += (known.empty() ? "" : ", ") + std::string(t.name);
  throw std::invalid_argument("unknown protocol '" + std::string(name) + "' (known: " + known + ")");
}

const ProtocolTraits& RowTraits(std::string_view name) {
  static const ProtocolTraits unknown{.name = "", .title = "", .relative_auc_reference = ""};
  const ProtocolTraits* t = Find(name);
  return t != nullptr ? *t : unknown;
}

}  // namespace dvpr
