#pragma once
// The radio's figures (issue 33; docs/network_model.md "Connectivity"), drawn only where the
// results have them (no "skipped" line elsewhere):
//   connectivity.png  from connectivity.csv: the share of the team's pairs in range and the
//                     number of components over time, one column per team size (every n up to
//                     three, else the largest), one line per radio variant
//   robots_in_range.png  from connectivity.csv: each robot's teammates in range over time (a
//                     heat map, robot by robot) and the number of components, the largest team,
//                     one panel per radio
//   radio_hops.png    from radio.csv's delivered_by_hops: the share of delivered copies that
//                     took 1, 2, ... hops, decentralized beside broadcast, the largest team, one
//                     panel per radio variant
//   radio_range.png   from runs.csv, when the sweep has radio variants of two or more ranges:
//                     bytes on the air per query of decentralized and broadcast, the share of
//                     queries answered (from queries.csv, when written; else the share of query
//                     copies delivered, from runs.csv) and the mean latency, against the range,
//                     one line per strategy and n; a bytes point whose share is under 90 % is
//                     circled and labelled with it (cheap only because the team is split)
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "experiments/figures/figures_traffic.h"
#include "experiments/results/results.h"

namespace dvpr {

// The legend name of network variant `variant` in `rows`: its radio label ("range 200m",
// "log_distance"), else its network name, else "network variant <v>".
std::string RadioLabelOf(const std::vector<RunResult>& rows, int variant);

// connectivity.png's data (conn_<n>.dat: per variant a block "time_s pairs_in_range
// share_of_pairs_percent components") from the first run and first strategy of `connectivity`
// (every strategy of a run has the same rows); `rows` name the variants. nullopt (and `why`)
// when the table has no row.
std::optional<FigureScript> WriteConnectivityFigure(const std::filesystem::path& data_dir, const CsvTable& connectivity,
                                                    const std::vector<RunResult>& rows, std::string& why);

// robots_in_range.png's data (in_range_<p>.dat, one per panel: index 0 "time_s robot
// robots_in_range", a blank line after each time; index 1 "time_s components") from connectivity.csv's robots_in_range: the largest
// team's first run and first strategy, one panel per radio (variants that differ only in routing
// have the same connectivity: the first of them). nullopt (and `why`) without such rows.
std::optional<FigureScript> WriteRobotsInRangeFigure(const std::filesystem::path& data_dir, const CsvTable& connectivity,
                                                     const std::vector<RunResult>& rows, std::string& why);

// radio_hops.png's data (hops_<p>.dat, one per panel: "hops decentralized_percent
// broadcast_percent", each strategy's copies summed over runs; NaN where it delivered none) from
// radio.csv's delivered_by_hops: the largest team, one panel per radio variant. nullopt (and
// `why`) without such rows.
std::optional<FigureScript> WriteRadioHopsFigure(const std::filesystem::path& data_dir, const CsvTable& radio,
                                                 const std::vector<RunResult>& rows, std::string& why);

// radio_range.png's data (radio_range.dat: per (strategy, n) a block "range_m bytes_per_query
// answered_percent mean_latency_ms delivered_percent", means over runs, NaN where unknown;
// delivered_percent: query_delivered_wire_bytes over query_copy_wire_bytes; radio_range_split.dat:
// "range_m bytes_per_query label" of the circled points); `queries` may be empty (no
// queries.csv: the middle panel draws delivered_percent). With `routing`, only the radio variants of that
// routing ("shortest_path", "link_state"; "" for direct), written as <name>.dat: a sweep of
// several routings draws one figure each.
std::optional<FigureScript> WriteRadioRangeFigure(const std::filesystem::path& data_dir, const std::vector<RunResult>& rows,
                                                  const CsvTable& queries, std::string& why,
                                                  const std::optional<std::string>& routing = std::nullopt,
                                                  const std::string& name = "radio_range");

// Both, for DrawFigures: (name, script) of each figure the results of out_dir have.
std::vector<std::pair<std::string, FigureScript>> RadioFigures(const std::filesystem::path& out_dir,
                                                               const std::filesystem::path& data_dir,
                                                               const std::vector<RunResult>& rows);

}  // namespace dvpr
