#pragma once
// The radio's range for real agents (docs/network_model.md, "The radio for real agents"): a
// launched team runs on the real network, where every robot hears every datagram; with
// `network.model: radio` each receiving agent drops, and counts, every message whose sender is
// out of its range at the receiver's agent time, so the processes face the disconnections the
// simulation's robots face. Positions are the simulation's (the KITTI split driven from agent
// time 0, RobotTracks), whether a robot hears another the simulation's propagation model (range
// or log_distance, seeded as the simulation's run). Emulation only: no relays (a launched team
// needs network.routing direct) and no store-and-forward.
#include <cstdint>
#include <memory>
#include <string>

#include "experiments/config/config.h"  // (and SimTime)

namespace dvpr {

struct Dataset;
struct SequenceSplit;

class EmulatedRange {
 public:
  // Throws std::invalid_argument "<origin>: network.<key>: ..." for a radio config a launched
  // team cannot emulate (relays, store-and-forward, a list of ranges: one team, one radio).
  static void CheckConfig(const ExperimentConfig& config, const std::string& origin);
  // The radio of `config` (which must list model radio) for robot `self` of the split's team,
  // its shadowing seeded with `run_seed`.
  EmulatedRange(const ExperimentConfig& config, const Dataset& data, const SequenceSplit& split, int self,
                std::uint64_t run_seed);
  ~EmulatedRange();
  EmulatedRange(const EmulatedRange&) = delete;
  EmulatedRange& operator=(const EmulatedRange&) = delete;

  // Whether this robot hears robot `src` at agent time `at`; before the team's start (at < 0)
  // every robot hears every other, so the start barrier is the real network's.
  bool Hears(int src, SimTime at);

 private:
  struct Radio;  // the simulation's positions and propagation (emulated_range.cpp)
  std::unique_ptr<Radio> radio_;
};

}  // namespace dvpr
