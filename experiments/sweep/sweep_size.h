#pragma once
// How large a sweep is, checked before it starts (issue 31): the number of runs and a rough,
// conservative estimate of the memory of one run. A sweep of more than kMaxSweepRuns runs (days
// of computing at a fraction of a second a run), or a run whose estimate exceeds the machine's
// physical memory, is refused with the count or the estimate, unless the user insists
// (`dvpr run --allow-large`). Before, a sweep of 1.8e9 runs was accepted and killed by the OOM
// killer while its runs were being listed, with no message.
#include <cstdint>
#include <string>

#include "experiments/config/config.h"

namespace dvpr {

inline constexpr double kMaxSweepRuns = 1e6;

struct SweepSize {
  // Rows of runs.csv: robot counts x runs x strategies x (1 for the paper protocol + the network
  // variants for sim). A double: the lists' products exceed int64 in a hostile config.
  double runs = 0;
  // One run of the largest team, an upper bound: every robot holding every descriptor
  // (robots x frames x dim x 4 bytes), plus with the paper protocol its neighbour lists
  // (frames x 64 candidates x 8 bytes: an index and a distance).
  double bytes_per_run = 0;
};

SweepSize EstimateSweepSize(const ExperimentConfig& config, std::int64_t frames, std::int64_t dim);

// The machine's physical memory in bytes (sysconf: pages x page size); 0 if unknown.
double PhysicalMemoryBytes();

// Throws ConfigError "<origin>: ..." naming the keys and the figures when the sweep is larger
// than kMaxSweepRuns or a run larger than physical_bytes (unless that is 0).
void CheckSweepSize(const SweepSize& size, double physical_bytes, const std::string& origin);

}  // namespace dvpr
