#include "net_models/propagation/propagation_registry.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

#include "net_models/propagation/full_mesh_propagation.h"
#include "net_models/propagation/log_distance_propagation.h"
#include "net_models/propagation/range_propagation.h"

namespace dvpr {

PropagationRegistry& PropagationRegistry::Global() {
  static PropagationRegistry registry = [] {
    PropagationRegistry r;
    // One line per model.
    r.Add({PropagationKind::kFullMesh, false, [](const PropagationParams&, const MobilityModel&, std::uint64_t) {
             return std::make_unique<FullMeshPropagation>();
           }});
    r.Add({PropagationKind::kRange, true, [](const PropagationParams& p, const MobilityModel& m, std::uint64_t) {
             return std::make_unique<RangePropagation>(m, p.range_m);
           }});
    r.Add({PropagationKind::kLogDistance, true, [](const PropagationParams& p, const MobilityModel& m, std::uint64_t seed) {
             return std::make_unique<LogDistancePropagation>(m, p.log_distance, seed);
           }});
    return r;
  }();
  return registry;
}

void PropagationRegistry::Add(PropagationModelInfo info) {
  if (!info.make) throw std::logic_error("PropagationRegistry: model '" + std::string(info.kind.name()) + "' has no factory");
  if (Find(info.kind) != nullptr) {
    throw std::logic_error("PropagationRegistry: model '" + std::string(info.kind.name()) + "' is registered already");
  }
  models_.push_back(std::move(info));
}

void PropagationRegistry::Remove(PropagationKind kind) {
  std::erase_if(models_, [&](const PropagationModelInfo& m) { return m.kind == kind; });
}

const PropagationModelInfo* PropagationRegistry::Find(PropagationKind kind) const {
  const auto it = std::find_if(models_.begin(), models_.end(), [&](const PropagationModelInfo& m) { return m.kind == kind; });
  return it == models_.end() ? nullptr : &*it;
}

std::unique_ptr<PropagationModel> MakePropagation(const PropagationParams& params, const MobilityModel& mobility,
                                                  std::uint64_t run_seed) {
  const PropagationModelInfo* m = PropagationRegistry::Global().Find(params.kind);
  if (m == nullptr) throw std::invalid_argument("propagation: unknown model '" + std::string(params.kind.name()) + "'");
  return m->make(params, mobility, run_seed);
}

}  // namespace dvpr
