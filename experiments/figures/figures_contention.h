#pragma once
// contention.png (issue 34; docs/network_model.md "Contending media"), drawn only where runs.csv
// has a variant that contends for its medium (`csma`, `wifi`; no "skipped" line elsewhere):
// against the offered load (every copy's wire bytes x 8 over the drive, one point per team size,
// labelled with it), the share of the offered load delivered (left) and the mean query latency
// (right), one line per (strategy, variant) of the media that share one channel - the ideal bus
// (`shared_medium`), csma and wifi - joining the team sizes in order: the strategy's colour, the
// medium's dash and point. Means over runs, bars of their 95 % confidence intervals. One legend
// for both panels, below them (it covers no data).
#include <filesystem>
#include <optional>
#include <string>

#include "experiments/figures/figures_traffic.h"

namespace dvpr {

// contention.dat (per (strategy, variant) a block "offered_mbps delivered_percent latency_ms
// offered_ci95 delivered_ci95_percent latency_ci95 n", ascending n) and its script; nullopt when no
// variant of `t` is csma or wifi.
std::optional<FigureScript> WriteContentionFigure(const std::filesystem::path& data_dir, const TrafficTable& t);

}  // namespace dvpr
