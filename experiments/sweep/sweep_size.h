#pragma once
// How large a sweep is, checked before it starts (issues 31 and 53): the number of runs, an
// estimate of the memory and the time of one run, and of the inputs made once. A sweep of more
// than kMaxSweepRuns runs, whose inputs and runs in flight at once (one per thread) need more
// than the machine's physical memory, or that would take more than kMaxSweepHours on this
// machine's cores, is refused with the count or the estimate and the config key of its largest
// term, unless the user insists (`dvpr run --allow-large`). Before, a sweep of 1.8e9 runs was
// killed by the OOM killer while its runs were being listed, and link-state beacons every
// microsecond, a staggered team 100000 h long with outputs.connectivity or 1 GiB verification
// requests ran for hours or were killed, all without a word.
//
// A run is one row of runs.csv: a robot count, a run, a strategy and a network variant. Its
// estimate is that of the costliest team of the sweep, each term on the costliest network
// variant and strategy for it (so a sum of terms no single run may have: an upper bound). The
// mission is when the team takes its last frame (SequenceSplit::LastCapture): ceil(frames / n) - 1
// frame periods for the paper's split of n robots; for a planned team its plan's latest capture
// (staggered and reverse: (n - 1) x offset + (frames - 1) / fps, each robot driving every frame;
// random_routes: at most (frames - 1) / fps; dataset.trajectories: the loaded plan's).
//
// Time of one run on one core (docs/config.md "Sweep size"), calibrated on docs/performance.md
// and rounded up; every robot in range of every other where range matters:
//  - search: frames^2 / 2 x dim multiply-adds, kSecondsPerMultiplyAdd each (every query against
//    every descriptor stored before it; the 100-robot broadcast's searches, 15 % of its 610 ms,
//    are 1.3e9);
//  - with sim, messages: 2 x frames x robots copies (a broadcast's queries and replies),
//    kSecondsPerMessage each (610 ms for 906 424);
//  - link_state beacons (network.routing on a radio): robots x (floor(mission / hello) + 1)
//    HELLOs and robots^2 x (floor(mission / topology) + 1) TCs (each origin's TC sent on once by
//    every robot), each transmission and each of its robots - 1 receptions kSecondsPerMessage;
//  - failover heartbeats (failover.enabled): robots x (floor(mission / heartbeat_period) + 1),
//    each sent and heard by robots - 1, kSecondsPerMessage each;
//  - store-and-forward retries (network.disconnected): every copy a robot may hold - its queries'
//    (frames x (robots - 1): a broadcast's, which every row runs, as the reference of the
//    descriptor strategies' relative AUC if not as its strategy) and with failover its
//    heartbeats' - asked again every retry period (DisconnectedParams::kRetry, 100 ms) while it is
//    held, min(hold_time, horizon - when it was sent) (its frames spread evenly over its drive),
//    and twice more (the retry that finds it expired or past the horizon and drops it, and one
//    for a copy sent between two retries), plus each holder's retry event every period until the
//    horizon and one past it: kSecondsPerMessage each. The horizon is the end of the mission, or
//    the last edge of a talk window (network.schedule) after it: past it no robot moves and no
//    window opens, so the network holds nothing longer (Network::SetHoldHorizon, set by
//    Scenario::Run) and drops what has no way yet at its first retry after it;
//  - verification requests: frames x request_bytes made, encoded and decoded (one request per
//    query at most), kSecondsPerRequestByte each;
//  - outputs.connectivity (radio): floor(mission x fps) + 1 steps, each kSecondsPerConnectivityStep
//    plus robots (robots - 1) / 2 pairs x kSecondsPerConnectivityPair;
//  - synthetic_bow, once before the runs: frames x (2 range_m)^2 x landmark_density landmarks,
//    kSecondsPerLandmark each (1.7 s a frame at the documented maxima).
// The default sweep's 760 runs come out at 0.37 s each (0.21 s measured, 80 s on 2 cores).
//
// Memory of one run (all its strategies: they run in turn, the broadcast reference's log alive):
//  - with sim, the stores: frames x copies (replicate_: max_replicas, else 1: each frame is kept
//    by one robot, in decentralized as in broadcast) x 2 x (6 dim + 12) bytes - the row, its
//    half-precision screen, its norm and entry, twice for the vectors' growth - and
//    kBytesPerFrameRecord a frame of records;
//  - with paper, kBytesPerFrameRecord a frame (routes and matches; the neighbour lists are an
//    input);
//  - verification payloads in flight: robots x (1 + in flight) x request_bytes + one being sent
//    or decoded: each robot keeps its request to refill it. In flight, at most its frames and what
//    its queues can hold on the variant that holds most (the largest queue and MTU, the fastest
//    rate, the longest latency): per queue of q packets the request on the wire, the whole ones
//    waiting, floor(q / the request's packets) (FifoTransmitter: the packet on the wire is not in
//    the queue), and those past it, propagating, floor(latency / its time on the wire) + 1; a
//    queue a destination on point_to_point, one a robot on the other models; one on ideal; none
//    where a request of more than q + 1 packets is dropped, and freed, as it is sent (20 robots'
//    60 MB requests over 400 frames: 1.17 GiB, 2.29 GiB with one in flight each as before; the
//    run's peak grew by 0.82 GiB under AddressSanitizer, 12 of the robots having sent one). Not
//    the requests a robot sends while one is on its way, ceil(transit x fps): a robot sends them
//    as its queries' replies come in, which a loaded link delays and bunches (4 robots' 200 kB
//    requests over 10 Mbit/s queues of 1000 packets: 13 of one robot in flight at once, where
//    that made 3);
//  - store-and-forward: kBytesPerHeldCopy a held copy and its message's wire bytes once (4 dim +
//    100 a query, 125 a heartbeat: a broadcast's copies share one payload, multi_probe_,
//    replicate_ and bow_ queries are a message a copy), at most robots x hold_bytes of wire bytes
//    (the buffers) and kBytesPerHeldCopy for each copy they can take. 100 robots holding every
//    broadcast query of 4541 frames of dim 16384: 0.34 GiB by this, and the run's peak grew by
//    0.37 GiB under AddressSanitizer (whose shadow and redzones add about an eighth); counting
//    every copy's wire bytes, as before, made it 27.5 GiB;
//  - outputs.connectivity: steps x (strategies + 1) x (kBytesPerConnectivityRow + 8 robots).
// Inputs, made once: the deployment's descriptors (frames x dim x 4), the training set's
// (synthetic: samples; deployment: frames; files: not counted), with paper the neighbour lists
// (frames x 64 x 8), and with a bow_ strategy on dataset.synthetic_bow its words and vectors at
// their largest, while TfIdfFromWords makes them: each frame's `features` int32 words, its term
// frequencies and its tf-idf vector (8 bytes a word it has: at most min(features, vocabulary)),
// 24 bytes a vector, and the idf's two tables of vocabulary entries, frames x (4 features + 16
// min(features, vocabulary) + 72) + 16 vocabulary bytes (not the landmarks the world draws
// around the trajectory; a BoW file is read, not counted).
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "experiments/config/config.h"
#include "experiments/domain/data/dataset.h"
#include "experiments/protocols/run.h"

namespace dvpr {

inline constexpr double kMaxSweepRuns = 1e6;
inline constexpr double kMaxSweepHours = 24;
inline constexpr double kSecondsPerMultiplyAdd = 1e-10;
inline constexpr double kSecondsPerMessage = 1e-6;
inline constexpr double kSecondsPerLandmark = 1.7 / (2000.0 * 2000.0 * 10.0);
// The 10^6-frame run made and decoded its 909 k requests of 25 000 bytes in 11 % of 60 s:
// 0.29 ns a byte, rounded up.
inline constexpr double kSecondsPerRequestByte = 5e-10;
// bench_connectivity: 28.8 us a step for 20 robots (190 pairs), 790 us for 100 (4950 pairs).
inline constexpr double kSecondsPerConnectivityStep = 1e-6;
inline constexpr double kSecondsPerConnectivityPair = 2e-7;
inline constexpr double kBytesPerFrameRecord = 256;
// A connectivity.csv row (288 bytes, twice for its vector's growth) or a step's snapshot.
inline constexpr double kBytesPerConnectivityRow = 600;
// A held copy (Network's HeldCopy, 40 bytes), twice for its vector's growth and twice while a
// retry refills the vector it takes the copies from.
inline constexpr double kBytesPerHeldCopy = 160;

// The terms of a run's estimate, each named in a refusal by the config keys that set it.
enum class SizeTerm { kSearch, kMessages, kBeacons, kHeartbeats, kRetries, kRequests, kConnectivity, kStores, kHeld };
inline constexpr std::size_t kSizeTerms = 9;

// One run of one team, term by term: what each term counts, and its seconds and bytes.
struct RunEstimate {
  int robots = 0;
  double frames = 0;     // the team's frames (every robot's)
  double mission_s = 0;  // when it takes its last frame
  double multiply_adds = 0;       // search
  double messages = 0;            // query and reply copies
  double stored = 0;              // descriptors the robots' stores keep (frames x copies)
  double beacons = 0;             // link_state HELLO and TC transmissions
  double heartbeats = 0;          // failover heartbeats sent
  double held_copies = 0;         // store-and-forward: copies a robot may hold
  double retries = 0;             // held copies asked again, and the holders' retry events
  double requests = 0;            // verification requests made (one a query at most)
  double request_bytes = 0;       // and their payload bytes
  double requests_in_flight = 0;  // a robot's at once
  double connectivity_steps = 0;  // outputs.connectivity rows of one strategy
  std::array<double, kSizeTerms> seconds{};  // by SizeTerm
  std::array<double, kSizeTerms> bytes{};
  double Seconds() const;
  double Bytes() const;
};

struct SweepSize {
  // Rows of runs.csv: robot counts x runs x strategies x (1 for the paper protocol + the network
  // variants for sim). A double: the lists' products exceed int64 in a hostile config.
  double runs = 0;
  // One run of the team whose run needs the most memory / takes longest, by the model above.
  double bytes_per_run = 0;
  double seconds_per_run = 0;
  // The inputs made once before the runs: synthetic_bow's vectors when a bow_ strategy runs on
  // them (0 otherwise: a BoW file is read, not made), and the inputs' memory.
  double input_seconds = 0;
  double input_bytes = 0;
  double bow_bytes = 0;  // of input_bytes: synthetic_bow's words and vectors while they are made
  RunEstimate largest;  // the run of bytes_per_run
  RunEstimate slowest;  // the run of seconds_per_run
  // The key of a planned team, whose plan sets the mission: "dataset.scenario",
  // "dataset.trajectories"; "" for the paper's split.
  std::string plan_key;
};

// Before the inputs are loaded: `frames` is the sequence's (dataset.frames); a planned scenario's
// team is worked out from it (staggered: every robot drives all `frames`).
SweepSize EstimateSweepSize(const ExperimentConfig& config, std::int64_t frames, std::int64_t dim);
// With the loaded deployment: its frames (every robot's for a planned team) and its plan's
// mission.
SweepSize EstimateSweepSize(const ExperimentConfig& config, const Dataset& deployment);

// The model's seconds of each of `specs` (a sweep of `config` on `deployment`): its protocol's
// terms for its team, on the sweep's costliest network variant and strategy, so that a team
// costs more than a smaller one where the messages, beacons, heartbeats, retries or
// connectivity steps grow with the robots. The progress's estimate weighs the runs by them
// (ExecutorOptions::run_seconds, RunProgress).
std::vector<double> RunSeconds(const ExperimentConfig& config, const Dataset& deployment,
                               const std::vector<RunSpec>& specs);

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

// Throws ConfigError "<origin>: <keys>: ..." with the figures when the sweep has more than
// kMaxSweepRuns runs, when input_bytes + the runs in flight at once (min(threads or cores, runs))
// x bytes_per_run exceed the machine's memory (unless that is 0), or when input_seconds + runs x
// seconds_per_run spread over min(runs in flight, cores) cores exceeds kMaxSweepHours. <keys>
// are those of the largest term: "robots, dataset" or "robots, runs, strategies, network,
// dataset" for the stores, searches and messages; otherwise the term's own key
// (network.routing, failover.heartbeat_period, network.disconnected, verification.request_bytes,
// outputs.connectivity), with dataset.scenario or dataset.trajectories after it when a planned
// team's mission sets it.
void CheckSweepSize(const SweepSize& size, const SweepMachine& machine, const std::string& origin);

}  // namespace dvpr
