#include "experiments/protocols/lcm/emulated_range.h"

#include <algorithm>
#include <memory>
#include <stdexcept>

#include <vector>

#include "experiments/domain/data/dataset.h"
#include "experiments/domain/data/split.h"
#include "experiments/domain/scenario/scenario.h"
#include "net_models/helper/network_helper.h"
#include "net_models/mobility/track_mobility.h"
#include "net_models/propagation/propagation_model.h"

namespace dvpr {

void EmulatedRange::CheckConfig(const ExperimentConfig& config, const std::string& origin) {
  const NetworkConfig& n = config.network;
  if (std::find(n.model.begin(), n.model.end(), LinkModelKind::kRadio) == n.model.end()) return;
  const auto fail = [&](const std::string& key, const std::string& problem) {
    throw std::invalid_argument(origin + ": network." + key + ": " + problem);
  };
  if (n.model.size() > 1) fail("model", "a launched team runs on one network: give radio alone");
  if (n.radio.size() > 1) fail("radio.range", "a launched team has one radio: give one range");
  if (n.routing != std::vector<NextHopEntry>{NextHopEntry{}}) {
    fail("routing", "real agents emulate the radio's range only, without relays: use direct");
  }
  if (n.disconnected.kind != DisconnectedKind::kDrop) {
    fail("disconnected", "real agents emulate the radio's range only, without store-and-forward: use drop");
  }
}

namespace {

NetworkModelParams RadioOf(const ExperimentConfig& config) {
  NetworkModelParams p;
  p.model = LinkModelKind::kRadio;
  p.propagation = config.network.radio.front();
  return p;
}

}  // namespace

struct EmulatedRange::Radio {
  NetworkStack stack;
  NodeId self;
  std::vector<Reception> reception = std::vector<Reception>(1);
};

EmulatedRange::EmulatedRange(const ExperimentConfig& config, const Dataset& data, const SequenceSplit& split,
                             int self, std::uint64_t run_seed)
    : radio_(std::make_unique<Radio>(Radio{
          MakeNetworkStack(RadioOf(config), static_cast<int>(split.ranges.size()), run_seed,
                           std::make_unique<TrackMobility>(RobotTracks(data, split))),
          NodeId(self)})) {}

EmulatedRange::~EmulatedRange() = default;

bool EmulatedRange::Hears(int src, SimTime at) {
  if (at < SimTime::Zero()) return true;
  const NodeId receiver[] = {radio_->self};
  radio_->stack.propagation->Reach(NodeId(src), receiver, at, radio_->reception);
  return radio_->reception.front().reaches;
}

}  // namespace dvpr
