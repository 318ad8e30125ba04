#include "experiments/sweep/sweep_size.h"

#include <unistd.h>

#include <algorithm>
#include <sstream>
#include <thread>

#include "experiments/results/protocol_traits.h"
#include "experiments/sweep/sweep.h"

namespace dvpr {

namespace {

// 3 significant digits: "1.8e+09", "4.19e+09", "760".
std::string Figure(double x) {
  std::ostringstream out;
  out.precision(3);
  out << x;
  return out.str();
}

std::string GiB(double bytes) { return Figure(bytes / (1024.0 * 1024.0 * 1024.0)) + " GiB"; }

// The number of network variants ExpandNetworks gives, without listing them (a hostile config's
// lists multiply to more variants than memory holds).
double NetworkVariants(const NetworkConfig& n) {
  double count = 0;
  for (const LinkModelKind model : n.model) {
    const bool wifi = model == LinkModelKind::kWifi;
    const bool radios_swept = model == LinkModelKind::kRadio || (wifi && n.wifi_radio);
    const double radios = radios_swept ? static_cast<double>(n.radio.size()) : 1.0;
    // wifi has its own rate: the bandwidth and latency lists do not multiply it (ExpandNetworks).
    const double rates = wifi ? 1.0 : static_cast<double>(n.bandwidth.size()) * static_cast<double>(n.latency.size());
    count += model == LinkModelKind::kIdeal ? 1.0
                                            : radios * rates * static_cast<double>(n.queue_packets.size()) *
                                                  static_cast<double>(n.mtu.size());
  }
  return count;
}

}  // namespace

SweepSize EstimateSweepSize(const ExperimentConfig& c, std::int64_t frames, std::int64_t dim) {
  const SweepConfig& s = c.sweep;
  SweepSize size;
  // One run per (robots, run) for each protocol, times the network variants of one on the
  // sweep's simulated network.
  double per_run_and_count = 0;
  for (const std::string& p : s.protocols) per_run_and_count += TraitsOf(p).simulated_network ? NetworkVariants(c.network) : 1.0;
  size.runs = static_cast<double>(s.robots.size()) * s.runs * static_cast<double>(s.strategies.size()) *
              per_run_and_count;
  const int largest = *std::max_element(s.robots.begin(), s.robots.end());
  size.bytes_per_run = static_cast<double>(largest) * static_cast<double>(frames) * static_cast<double>(dim) * 4.0;
  if (AnyProtocol(s.protocols, &ProtocolTraits::static_evaluation)) size.bytes_per_run += static_cast<double>(frames) * 64 * 8;
  const double f = static_cast<double>(frames);
  size.seconds_per_run = f * f / 2 * static_cast<double>(dim) * kSecondsPerMultiplyAdd;
  if (AnyProtocol(s.protocols, &ProtocolTraits::simulated_network)) size.seconds_per_run += 2 * f * largest * kSecondsPerMessage;
  const bool bow = std::any_of(s.strategies.begin(), s.strategies.end(), [](const StrategySpec& x) { return x.bag_of_words(); });
  if (bow && !c.dataset.bow) {
    const SyntheticBowParams p = c.dataset.synthetic_bow.value_or(SyntheticBowParams{});
    size.input_seconds = f * (2 * p.range_m) * (2 * p.range_m) * p.landmark_density * kSecondsPerLandmark;
  }
  return size;
}

SweepMachine SweepMachine::ThisOne(int threads) {
  return {.memory_bytes = PhysicalMemoryBytes(),
          .cores = std::max(1, static_cast<int>(std::thread::hardware_concurrency())),
          .threads = threads};
}

double PhysicalMemoryBytes() {
  const long pages = sysconf(_SC_PHYS_PAGES);
  const long page = sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || page <= 0) return 0;
  return static_cast<double>(pages) * static_cast<double>(page);
}

void CheckSweepSize(const SweepSize& size, const SweepMachine& machine, const std::string& origin) {
  if (size.runs > kMaxSweepRuns) {
    throw ConfigError(origin + ": robots, runs, protocols, strategies, network: the sweep has " + Figure(size.runs) +
                      " runs (robot counts x runs x strategies x network variants), more than " +
                      Figure(kMaxSweepRuns) + " (days of computing); narrow it, or pass --allow-large to run it anyway");
  }
  const int cores = std::max(1, machine.cores);
  // Runs in flight at once: one per thread (ParallelFor), never more than there are runs.
  const double at_once = std::max(1.0, std::min(static_cast<double>(machine.threads > 0 ? machine.threads : cores), size.runs));
  const double bytes = at_once * size.bytes_per_run;
  if (machine.memory_bytes > 0 && bytes > machine.memory_bytes) {
    const std::string what = at_once > 1 ? Figure(at_once) + " runs at once (one a thread) may need up to " + GiB(bytes) +
                                               ", each up to " + GiB(size.bytes_per_run)
                                         : "a run may need up to " + GiB(bytes);
    throw ConfigError(origin + ": robots, dataset: " + what +
                      " (largest team x frames x dim x 4 bytes of descriptors, and the paper protocol's " +
                      "neighbour lists), more than this machine's " + GiB(machine.memory_bytes) +
                      " of memory; lower dataset.frames, dataset.dim or robots" +
                      (at_once > 1 ? std::string(", run fewer at once (--threads)") : "") +
                      ", or pass --allow-large to run it anyway");
  }
  const double parallel = std::min(at_once, static_cast<double>(cores));
  const double seconds = size.input_seconds + size.runs * size.seconds_per_run / parallel;
  if (seconds > kMaxSweepHours * 3600) {
    throw ConfigError(origin + ": robots, runs, strategies, network, dataset: the sweep would take about " +
                      Figure(seconds / 3600) + " h on " + Figure(parallel) + (parallel > 1 ? " cores (" : " core (") +
                      Figure(size.runs) + (size.runs == 1 ? " run" : " runs") + " of up to " + Figure(size.seconds_per_run) + " s each" +
                      (size.input_seconds > 0 ? ", and " + Figure(size.input_seconds) +
                                                    " s to make dataset.synthetic_bow's vectors"
                                              : std::string()) +
                      "), more than " + Figure(kMaxSweepHours) +
                      " h; narrow it, or pass --allow-large to run it anyway");
  }
}

}  // namespace dvpr
