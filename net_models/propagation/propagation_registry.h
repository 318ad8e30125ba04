#pragma once
// The propagation models a network can be built with, by name (ns-3's TypeId lookup in small):
// each entry says whether the model needs the robots' positions and how to build one from a
// PropagationParams. The config's `propagation` names an entry (ParsePropagationKind), and the
// network helper builds it (MakePropagation) without knowing which models exist.
//
// A new propagation model is its class in this room and one line in Global()'s list
// (propagation_registry.cpp); a program or a test may register one of its own for a scope
// (PropagationRegistration; tests/net_models/helper/test_propagation_registry.cpp).
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string_view>
#include <vector>

#include "net_models/mobility/mobility_model.h"
#include "net_models/propagation/propagation_model.h"
#include "net_models/propagation/propagation_params.h"

namespace dvpr {

struct PropagationModelInfo {
  using Factory = std::function<std::unique_ptr<PropagationModel>(const PropagationParams& params,
                                                                  const MobilityModel& mobility, std::uint64_t run_seed)>;
  PropagationKind kind;         // its config name (a string literal)
  bool needs_positions = true;  // false: who hears whom never depends on where the robots are
  Factory make;                 // `mobility` outlives the model; run_seed seeds a random one
};

class PropagationRegistry {
 public:
  // The models of a network: full_mesh, range and log_distance, in that order (the order of the
  // names an unknown one is told), then any registered since.
  static PropagationRegistry& Global();

  // Throws std::logic_error when the name is taken or `make` is empty.
  void Add(PropagationModelInfo info);
  // Forgets the model of `kind` (nothing when none).
  void Remove(PropagationKind kind);
  // The entry of `kind`; null when none has its name.
  const PropagationModelInfo* Find(PropagationKind kind) const;
  std::span<const PropagationModelInfo> models() const { return models_; }

 private:
  std::vector<PropagationModelInfo> models_;
};

// Registers a model in the global registry for the object's lifetime (a test's model; not while
// another thread builds networks).
class PropagationRegistration {
 public:
  explicit PropagationRegistration(PropagationModelInfo info) : kind_(info.kind) {
    PropagationRegistry::Global().Add(std::move(info));
  }
  ~PropagationRegistration() { PropagationRegistry::Global().Remove(kind_); }
  PropagationRegistration(const PropagationRegistration&) = delete;
  PropagationRegistration& operator=(const PropagationRegistration&) = delete;

 private:
  PropagationKind kind_;
};

// The model `params` names, over `mobility`; throws std::invalid_argument "propagation: unknown
// model '<name>'" when none is registered under its name.
std::unique_ptr<PropagationModel> MakePropagation(const PropagationParams& params, const MobilityModel& mobility,
                                                  std::uint64_t run_seed);

}  // namespace dvpr
