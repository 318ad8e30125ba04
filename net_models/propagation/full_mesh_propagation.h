#pragma once
// "full_mesh": every node hears every other at once, wherever they are: the wired team of the
// paper and dvpr's default. The link model's latency is the whole delay; nothing is out of range.
#include "net_models/propagation/propagation_model.h"

namespace dvpr {

class FullMeshPropagation final : public PropagationModel {
 private:
  // Every outcome arrives preset to {reaches, no added delay}: nothing to change.
  void DoReach(NodeId, std::span<const NodeId>, SimTime, std::span<Reception>) override {}
  std::string_view DoName() const override { return "full_mesh"; }
  bool DoChangesOverTime() const override { return false; }
};

}  // namespace dvpr
