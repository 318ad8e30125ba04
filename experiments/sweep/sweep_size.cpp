#include "experiments/sweep/sweep_size.h"

#include <unistd.h>

#include <algorithm>
#include <sstream>

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

bool Has(const std::vector<std::string>& protocols, const char* name) {
  return std::find(protocols.begin(), protocols.end(), name) != protocols.end();
}

// The number of network variants ExpandNetworks gives, without listing them (a hostile config's
// lists multiply to more variants than memory holds).
double NetworkVariants(const NetworkConfig& n) {
  double count = 0;
  for (const LinkModelKind model : n.model) {
    count += model == LinkModelKind::kIdeal ? 1.0
                                            : static_cast<double>(n.bandwidth.size()) * static_cast<double>(n.latency.size()) *
                                                  static_cast<double>(n.queue_packets.size()) * static_cast<double>(n.mtu.size());
  }
  return count;
}

}  // namespace

SweepSize EstimateSweepSize(const ExperimentConfig& c, std::int64_t frames, std::int64_t dim) {
  const SweepConfig& s = c.sweep;
  SweepSize size;
  const double per_run_and_count = (Has(s.protocols, "paper") ? 1.0 : 0.0) +
                                   (Has(s.protocols, "sim") ? NetworkVariants(c.network) : 0.0);
  size.runs = static_cast<double>(s.robots.size()) * s.runs * static_cast<double>(s.strategies.size()) *
              per_run_and_count;
  const int largest = *std::max_element(s.robots.begin(), s.robots.end());
  size.bytes_per_run = static_cast<double>(largest) * static_cast<double>(frames) * static_cast<double>(dim) * 4.0;
  if (Has(s.protocols, "paper")) size.bytes_per_run += static_cast<double>(frames) * 64 * 8;
  return size;
}

double PhysicalMemoryBytes() {
  const long pages = sysconf(_SC_PHYS_PAGES);
  const long page = sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || page <= 0) return 0;
  return static_cast<double>(pages) * static_cast<double>(page);
}

void CheckSweepSize(const SweepSize& size, double physical_bytes, const std::string& origin) {
  if (size.runs > kMaxSweepRuns) {
    throw ConfigError(origin + ": robots, runs, protocols, strategies, network: the sweep has " + Figure(size.runs) +
                      " runs (robot counts x runs x strategies x network variants), more than " +
                      Figure(kMaxSweepRuns) + " (days of computing); narrow it, or pass --allow-large to run it anyway");
  }
  if (physical_bytes > 0 && size.bytes_per_run > physical_bytes) {
    throw ConfigError(origin + ": robots, dataset: a run may need up to " + GiB(size.bytes_per_run) +
                      " (largest team x frames x dim x 4 bytes of descriptors, and the paper protocol's " +
                      "neighbour lists), more than this machine's " + GiB(physical_bytes) +
                      " of memory; lower dataset.frames, dataset.dim or robots, or pass --allow-large to run it anyway");
  }
}

}  // namespace dvpr
