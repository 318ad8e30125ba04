#pragma once
// How large a sweep is, checked before it starts (issue 31): the number of runs, a rough,
// conservative estimate of the memory of one run and of its time, and the time of the inputs
// made once (synthetic_bow's vectors). A sweep of more than kMaxSweepRuns runs, runs in flight at
// once (one per thread) whose memory exceeds the machine's physical memory, or a sweep that would
// take more than kMaxSweepHours on this machine's cores, is refused with the count or the
// estimate, unless the user insists (`dvpr run --allow-large`). Before, a sweep of 1.8e9 runs was
// accepted and killed by the OOM killer while its runs were being listed, with no message, and
// synthetic_bow at its largest parameters took hours without a word.
//
// The time model (docs/config.md "Sweep size"), calibrated on the figures of docs/performance.md
// and rounded up:
//  - search: every query against every descriptor stored before it (brute force, as
//    IncrementalIndex searches): frames^2 / 2 x dim multiply-adds, kSecondsPerMultiplyAdd each
//    (the 100-robot broadcast: its searches, 15 % of 610 ms, are 1.3e9 multiply-adds);
//  - with sim: every frame's query sent to every robot of the largest team and answered:
//    2 x frames x robots messages, kSecondsPerMessage each (610 ms for 906 424 messages);
//  - synthetic_bow, once: every landmark of the square of side 2 x range_m around each frame is
//    examined: frames x (2 range_m)^2 x landmark_density, kSecondsPerLandmark each (1.7 s a frame
//    at the documented maxima, range_m 1000 and landmark_density 10: 4e7 landmarks).
// The default sweep's 760 runs come out at 0.31 s each (0.21 s measured, 80 s on 2 cores).
#include <cstdint>
#include <string>

#include "experiments/config/config.h"

namespace dvpr {

inline constexpr double kMaxSweepRuns = 1e6;
inline constexpr double kMaxSweepHours = 24;
inline constexpr double kSecondsPerMultiplyAdd = 1e-10;
inline constexpr double kSecondsPerMessage = 1e-6;
inline constexpr double kSecondsPerLandmark = 1.7 / (2000.0 * 2000.0 * 10.0);

struct SweepSize {
  // Rows of runs.csv: robot counts x runs x strategies x (1 for the paper protocol + the network
  // variants for sim). A double: the lists' products exceed int64 in a hostile config.
  double runs = 0;
  // One run of the largest team, an upper bound: every robot holding every descriptor
  // (robots x frames x dim x 4 bytes), plus with the paper protocol its neighbour lists
  // (frames x 64 candidates x 8 bytes: an index and a distance).
  double bytes_per_run = 0;
  // One run of the largest team on one core, by the time model above.
  double seconds_per_run = 0;
  // The inputs made once before the runs: synthetic_bow's vectors when a bow_ strategy runs on
  // them (0 otherwise: a BoW file is read, not made).
  double input_seconds = 0;
};

SweepSize EstimateSweepSize(const ExperimentConfig& config, std::int64_t frames, std::int64_t dim);

// The machine a sweep is checked against.
struct SweepMachine {
  double memory_bytes = 0;  // physical memory; 0: unknown, not checked
  int cores = 1;            // cores the runs share
  int threads = 0;          // dvpr run --threads: runs in flight at once; 0: one per core
  // The machine dvpr runs on: PhysicalMemoryBytes() and std::thread::hardware_concurrency().
  static SweepMachine ThisOne(int threads);
};

// The machine's physical memory in bytes (sysconf: pages x page size); 0 if unknown.
double PhysicalMemoryBytes();

// Throws ConfigError "<origin>: ..." naming the keys and the figures when the sweep has more
// than kMaxSweepRuns runs, when the runs in flight at once (min(threads or cores, runs)) may need
// more than the machine's memory (unless that is 0), or when input_seconds + runs x
// seconds_per_run spread over min(runs in flight, cores) cores exceeds kMaxSweepHours.
void CheckSweepSize(const SweepSize& size, const SweepMachine& machine, const std::string& origin);

}  // namespace dvpr
