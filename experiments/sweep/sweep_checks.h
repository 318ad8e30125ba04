#pragma once
// The checks of a sweep that need its loaded inputs but no run: `dvpr run` calls CheckSweepInputs
// after LoadSharedInputs and before it writes anything, so an input that would fail a run fails
// first, with one line naming the key or file and nothing on disk. (The config reader checks
// what the config alone decides; LoadSharedInputs what the data files decide.)
#include <string>

#include "experiments/protocols/run.h"

namespace dvpr {

// Throws ConfigError "<origin>: <key>: <problem>" when
//  - a centroid file of the sweep (training.centroids, every robots count and run, for the
//    clusters per robot of every strategy that reads it) is not robots x C finite values of the
//    descriptors' width: the error names the file;
//  - a strategy needs the training descriptors (balanced_, _train) but centroid files replace them,
//    or clusters them into more clusters than there are descriptors;
//  - with the sim protocol, a network variant is invalid for a team of the sweep, e.g. a link
//    override (network.links) naming a robot outside the smallest team.
void CheckSweepInputs(const SharedInputs& inputs, const std::string& origin);

}  // namespace dvpr
