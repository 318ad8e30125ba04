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
//    override (network.links) naming a robot outside the smallest team;
//  - with failover on in the sim protocol, failover.timeout is shorter than heartbeat_period plus
//    the worst delay of a heartbeat on a network variant (docs/failover.md);
//  - a dropout is at or after the end of the run of a team that has its robot;
//  - unless allow_large, the sweep has more than kMaxSweepRuns runs, its runs in flight at once
//    (`threads`, 0: one per core) may need more than the machine's memory, or it would take more
//    than kMaxSweepHours on this machine's cores (sweep_size.h).
void CheckSweepInputs(const SharedInputs& inputs, const std::string& origin, bool allow_large = false,
                      int threads = 0);

}  // namespace dvpr
