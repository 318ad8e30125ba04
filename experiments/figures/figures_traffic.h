#pragma once
// The traffic figures of the simulation (issue 16), one message each:
//   place_recognition_bytes.png  place-recognition bytes per query vs n, decentralized against
//                                broadcast, the n - 1 law drawn and the measured ratio labelled
//   traffic_by_role.png          all traffic per query, stacked by message role, per strategy
//   robot_load.png               searches served per robot in one run, fair share, busiest robot;
//                                one y scale for all its panels (they are compared)
//   traffic_matrix.png           sender x receiver bytes of one run
//   saturation.png               offered vs delivered load and latency vs bandwidth, shared medium
//   loop_closures.png            robot pairs with an inter-robot loop closure over time, and each
//                                pair's first one (figures_closures.cpp)
// Each Write* writes its data files into data_dir and returns the gnuplot commands that draw
// them (without terminal and output, which DrawFigures puts in front), or nullopt when the
// results hold nothing to draw (then `why` says what is missing). None draws a panel without data.
//
// Per network variant (issue 48): traffic_by_role, robot_load, traffic_matrix and loop_closures
// show one network each. With one sim network variant they are <name>.png as ever; with several,
// DrawFigures draws each for every variant, <name>-net<v>-<slug>.png (VariantFigures: v the
// network_variant of runs.csv, zero-padded to the width of the largest so that the files list in
// variant order, slug its network name in lower case, e.g.
// traffic_by_role-net1-point-to-point-10-mbit-s-2-ms.png), the title naming the network and the
// data files prefixed net<v>_. place_recognition_bytes and saturation compare the networks in
// one figure.
#include <array>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "experiments/results/results.h"

namespace dvpr {

// Means over the runs of one (strategy, network variant, n) of protocol sim, and their spread:
// the half-width of each mean's 95 % confidence interval (Student's t over the runs, spread.h;
// 0 below 2 runs, where there is no spread to draw).
struct TrafficCell {
  int runs = 0;
  double pr_bytes_per_query = 0;  // PlaceRecognitionBytesPerQuery
  std::array<double, kMessageRoles> role_bytes_per_query{};  // offered wire bytes of every copy
  double offered_mbps = 0;        // offered wire bytes of every copy x 8 / duration
  double delivered_mbps = 0;
  double latency_ms = 0;          // a run without a latency counts 0, as in the mean
  double longest_drive_s = 0;     // the longest duration_s of the runs
  double pr_bytes_ci95 = 0;
  double total_bytes_ci95 = 0;    // of the sum of role_bytes_per_query
  double offered_ci95 = 0;
  double delivered_ci95 = 0;
  double latency_ci95 = 0;
  // Each run's PlaceRecognitionBytesPerQuery by run index: the strategies' runs of one index
  // share their seed, so the broadcast / decentralized ratio has a value per run (its spread).
  std::map<int, double> pr_bytes_by_run;
};

struct TrafficTable {
  std::vector<std::string> strategies;  // every strategy of runs.csv, in order (its colour)
  std::vector<NetworkLabel> networks;   // sim variants with bytes by role, by variant index
  std::vector<int> robots;              // ascending
  bool sim_rows = false;                // runs.csv has sim rows with bytes by role (with queries or not)
  std::map<std::tuple<std::string, int, int>, TrafficCell> cells;
  const TrafficCell* Find(const std::string& strategy, int variant, int robots) const;
  std::size_t StrategyIndex(const std::string& strategy) const;
  int ShownVariant() const;             // -1: no sim rows with bytes by role
  const NetworkLabel* Network(int variant) const;
};
TrafficTable TabulateTraffic(const std::vector<RunResult>& rows);
// Why `t` has no cell: "needs protocol sim", or that its sim runs sent no query.
std::string NoSimTraffic(const TrafficTable& t);

// A CSV file as strings, for the per-run files (per_robot.csv, links.csv). Empty if unreadable.
struct CsvTable {
  std::filesystem::path path;
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;  // rows[i] is line i + 2 of the file
  std::size_t Column(const std::string& name) const;  // throws if absent
  // Field `column` of rows[row] as an integer in [lo, hi], or as a finite number >= 0 (a robot id
  // or a count goes into a script or an index: nothing else is let through). Throws
  // std::runtime_error naming the file, line and column.
  int Integer(std::size_t row, std::size_t column, int lo, int hi) const;
  double Count(std::size_t row, std::size_t column) const;
};
CsvTable ReadCsvTable(const std::filesystem::path& path);

// Which network variant a per-variant figure draws and how its files are named.
struct VariantFigure {
  int variant = -1;          // network_variant; -1 with no sim variant (nothing to draw)
  std::string suffix;        // of the PNG's stem: "" (the only variant) or "-net<v>-<slug>"
  std::string data_prefix;   // of its data files: "" or "net<v>_"
};
// One entry per sim network variant with bytes of `t` (one entry, suffix "", for none or one).
std::vector<VariantFigure> VariantFigures(const TrafficTable& t);
// The network's name as a file-name part: lower case letters, digits and '.', runs of anything
// else one '-', at most 48 characters ("point-to-point-10-mbit-s-2-ms").
std::string NetworkSlug(const NetworkLabel& network);

struct FigureScript {
  std::string body;
  int width = 1400;
  int height = 600;
};

std::optional<FigureScript> WritePlaceRecognitionFigure(const std::filesystem::path& data_dir, const TrafficTable& t,
                                                        std::string& why);
// The per-variant figures: `view` names the variant (by default, variant -1: ShownVariant) and
// the prefix of the data files.
std::optional<FigureScript> WriteRoleFigure(const std::filesystem::path& data_dir, const TrafficTable& t,
                                            std::string& why, const VariantFigure& view = {});
std::optional<FigureScript> WriteRobotLoadFigure(const std::filesystem::path& data_dir, const TrafficTable& t,
                                                 const CsvTable& per_robot, std::string& why,
                                                 const VariantFigure& view = {});
std::optional<FigureScript> WriteMatrixFigure(const std::filesystem::path& data_dir, const TrafficTable& t,
                                              const CsvTable& links, std::string& why, const VariantFigure& view = {});
// loop_closures.png (figures_closures.cpp), from closure_pairs.csv: the share of pairs closed
// over time, and a first-closure matrix for each of the first two strategies whose run closed a
// pair; nullopt when no run of the variant closed one (nothing but zeros to draw).
std::optional<FigureScript> WriteClosureFigure(const std::filesystem::path& data_dir, const TrafficTable& t,
                                               const CsvTable& closure_pairs, std::string& why,
                                               const VariantFigure& view = {});
std::optional<FigureScript> WriteSaturationFigure(const std::filesystem::path& data_dir, const TrafficTable& t,
                                                  std::string& why);

}  // namespace dvpr
