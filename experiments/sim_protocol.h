#pragma once
// Protocol "sim" of `dvpr run`: for each (robots, run, network variant) the
// team runs in virtual time once per strategy, on the same data and
// centroids as the paper protocol's run; broadcast is the reference of the
// relative AUC (DESIGN.md section 3).
#include <memory>
#include <string>

#include "agents/centroid_table.h"
#include "agents/routing.h"
#include "experiments/config.h"
#include "experiments/run_executor.h"
#include "net_models/link_factory.h"

namespace dvpr {

// The typed `network:` settings of one sweep variant as the link factory's parameters.
NetworkModelParams ToNetworkModelParams(const NetworkSettings& settings);

// The routing strategy `name` for a team of `robots` over `table`.
// Throws std::invalid_argument for a name it does not know.
std::unique_ptr<RoutingStrategy> MakeStrategy(const std::string& name, std::shared_ptr<const CentroidTable> table,
                                              int robots);

RunFunction MakeSimRun(const SharedInputs& inputs);

}  // namespace dvpr
