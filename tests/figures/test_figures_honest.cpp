// Issue 48's figure rules that the figures' data and scripts can show (pixels are not tested):
// every general figure is drawn for each network variant, a skipped figure says the real reason,
// no drawn figure has a panel without data, and the confusion matrix's data stays small.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "experiments/figures/figures.h"
#include "experiments/figures/figures_traffic.h"
#include "experiments/figures/gnuplot_run.h"
#include "experiments/results/closure_rows.h"
#include "experiments/results/result_writers.h"
#include "tests/figures/figures_test_support.h"
#include "tests/test_support.h"

namespace dvpr {
namespace {

using dvpr::testing_support::Slurp;
namespace fs = std::filesystem;

using testing_support::Net;

// A sim run of 4 robots: 100 queries over 10 s, 700 bytes of queries and replies, no revisit
// (relative AUC not applicable, both AUCs 0, no relevant query).
RunResult SimRun(const std::string& strategy, int run, const NetworkLabel& net) {
  RunResult r;
  r.key = RunKey{.protocol = "sim", .strategy = strategy, .robots = 4, .run = run, .network = net};
  r.queries = 100;
  r.duration_s = 10;
  r.mean_latency_ms = 5;
  r.auc = 0;
  r.auc_reference = 0;
  RunRoleBytes b;
  b.copies[0].wire = 600;
  b.copies[1].wire = 100;
  for (CopyBytes& c : b.copies) c.delivered_wire = c.wire;
  r.roles = b;
  r.closures = RunClosures{};
  return r;
}

class HonestFigures : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = dvpr::testing_support::FreshTestDir("figures_honest");
    fs::create_directories(dir_ / "figures" / "data");
  }
  // Both strategies, run 0, on every network of `nets`.
  static std::vector<RunResult> Rows(const std::vector<NetworkLabel>& nets) {
    std::vector<RunResult> rows;
    for (const NetworkLabel& n : nets) {
      for (const char* s : {"decentralized", "broadcast"}) rows.push_back(SimRun(s, 0, n));
    }
    return rows;
  }
  // per_robot.csv, links.csv and closure_pairs.csv of those runs; decentralized's run 0 closes
  // pair (0, 1) at `closes_at` ns on every network when given, broadcast's never.
  void WriteRunFiles(const std::vector<RunResult>& rows, std::optional<std::int64_t> closes_at) const {
    std::string per_robot = "protocol,strategy,robots,run,robot,queries_received,network_variant\n";
    std::string links = "protocol,strategy,robots,run,src,dst,wire_bytes,network_variant\n";
    std::string pairs = std::string(kClosurePairsHeader) + "\n";
    for (const RunResult& r : rows) {
      const std::string key = "sim," + r.key.strategy + ",4,0,";
      const std::string v = std::to_string(r.key.network.variant);
      for (int robot = 0; robot < 4; ++robot) per_robot += key + std::to_string(robot) + ",25," + v + "\n";
      links += key + "0,1,700," + v + "\n";
      for (int a = 0; a < 4; ++a) {
        for (int b = a + 1; b < 4; ++b) {
          const bool closed = closes_at && r.key.strategy == "decentralized" && a == 0 && b == 1;
          pairs += CsvRow(ClosurePairRow{r.key, a, b, closed ? closes_at : std::nullopt}) + "\n";
        }
      }
    }
    std::ofstream(dir_ / "per_robot.csv") << per_robot;
    std::ofstream(dir_ / "links.csv") << links;
    std::ofstream(dir_ / "closure_pairs.csv") << pairs;
  }
  // Both strategies on point-to-point 10 Mbit/s and a 100 Mbit/s shared medium, decentralized
  // closing its pair at 2 s: the run files written and every figure drawn (notes on `log`).
  struct Drawn {
    std::vector<RunResult> rows;
    std::vector<fs::path> pngs;
  };
  Drawn DrawTwoNetworks(std::ostream& log) const {
    std::vector<RunResult> rows = Rows({Net(0, "point_to_point", 1e7), Net(1, "shared_medium", 1e8)});
    WriteRunsCsv(dir_ / "runs.csv", rows);
    WriteRunFiles(rows, 2'000'000'000);
    std::vector<fs::path> pngs = DrawFigures(dir_, testing_support::NetworkLabelsOf(rows), log);
    return {std::move(rows), std::move(pngs)};
  }
  std::set<std::string> Pngs() const {
    std::set<std::string> out;
    for (const auto& e : fs::directory_iterator(dir_ / "figures")) {
      if (e.path().extension() == ".png") out.insert(e.path().filename().string());
    }
    return out;
  }
  fs::path dir_;
};

// The slug is the network's name in lower case, anything but letters, digits and '.' one '-'.
TEST_F(HonestFigures, NetworkSlugsByHand) {
  EXPECT_EQ(NetworkSlug(Net(0, "point_to_point", 1e7)), "point-to-point-10-mbit-s-2-ms");
  EXPECT_EQ(NetworkSlug(Net(3, "shared_medium", 1e8)), "shared-medium-100-mbit-s-2-ms");
  const TrafficTable one = TabulateTraffic(Rows({Net(0, "point_to_point", 1e7)}));
  ASSERT_EQ(VariantFigures(one).size(), 1u);
  EXPECT_EQ(VariantFigures(one)[0].suffix, "");       // the only network: the usual names
  EXPECT_EQ(VariantFigures(one)[0].data_prefix, "");
  const TrafficTable two = TabulateTraffic(Rows({Net(0, "point_to_point", 1e7), Net(1, "shared_medium", 1e8)}));
  ASSERT_EQ(VariantFigures(two).size(), 2u);
  EXPECT_EQ(VariantFigures(two)[1].variant, 1);
  EXPECT_EQ(VariantFigures(two)[1].suffix, "-net1-shared-medium-100-mbit-s-2-ms");
  EXPECT_EQ(VariantFigures(two)[1].data_prefix, "net1_");
  // Eleven variants (0 .. 10, as radio_kitti00.yaml): net00 .. net10, so they list in order.
  const TrafficTable eleven = TabulateTraffic(Rows({Net(0, "point_to_point", 1e7), Net(10, "shared_medium", 1e8)}));
  ASSERT_EQ(VariantFigures(eleven).size(), 2u);
  EXPECT_EQ(VariantFigures(eleven)[0].suffix, "-net00-point-to-point-10-mbit-s-2-ms");
  EXPECT_EQ(VariantFigures(eleven)[1].suffix, "-net10-shared-medium-100-mbit-s-2-ms");
  EXPECT_EQ(VariantFigures(eleven)[0].data_prefix, "net00_");
}

// Two network variants: traffic_by_role, robot_load, traffic_matrix and loop_closures once per
// network, named by it (and titled with it); the figures that compare the networks once. Drawn
// again from the files (as `dvpr plot` does), the same set.
TEST_F(HonestFigures, TwoVariantsDrawEachGeneralFigurePerNetwork) {
  if (!FindProgram("gnuplot")) GTEST_SKIP() << "gnuplot is not installed";
  std::ostringstream log;
  const auto [rows, drawn] = DrawTwoNetworks(log);
  std::set<std::string> expected = {"place_recognition_bytes.png", "saturation.png"};
  for (const char* name : {"traffic_by_role", "robot_load", "traffic_matrix", "loop_closures"}) {
    expected.insert(std::string(name) + "-net0-point-to-point-10-mbit-s-2-ms.png");
    expected.insert(std::string(name) + "-net1-shared-medium-100-mbit-s-2-ms.png");
  }
  EXPECT_EQ(Pngs(), expected) << log.str();
  EXPECT_EQ(drawn.size(), expected.size());
  EXPECT_NE(Slurp(dir_ / "figures" / "data" / "robot_load-net1-shared-medium-100-mbit-s-2-ms.gp")
                .find("shared medium 100 Mbit/s 2 ms"),
            std::string::npos);
  std::ostringstream again;
  EXPECT_EQ(DrawFigures(dir_, testing_support::NetworkLabelsOf(rows), again).size(), expected.size());
  EXPECT_EQ(Pngs(), expected) << again.str();
}

// One network variant: the names of every earlier version.
TEST_F(HonestFigures, OneVariantKeepsTheUsualNames) {
  if (!FindProgram("gnuplot")) GTEST_SKIP() << "gnuplot is not installed";
  const std::vector<RunResult> rows = Rows({Net(0, "point_to_point", 1e7)});
  WriteRunsCsv(dir_ / "runs.csv", rows);
  WriteRunFiles(rows, 2'000'000'000);
  std::ostringstream log;
  DrawFigures(dir_, testing_support::NetworkLabelsOf(rows), log);
  EXPECT_EQ(Pngs(), (std::set<std::string>{"place_recognition_bytes.png", "traffic_by_role.png", "robot_load.png",
                                           "traffic_matrix.png", "loop_closures.png"}))
      << log.str();
  EXPECT_TRUE(fs::exists(dir_ / "figures" / "data" / "roles_0.dat"));
  EXPECT_TRUE(fs::exists(dir_ / "figures" / "data" / "closures.dat"));
}

// The data files a script plots ('name.dat' or 'name.f32' in a plot command).
std::vector<std::string> PlottedFiles(const std::string& script) {
  std::vector<std::string> files;
  // Single-quoted strings, in order ('' inside one is a quote: never in a file name here).
  for (std::size_t open = script.find('\''); open != std::string::npos;) {
    const std::size_t close = script.find('\'', open + 1);
    if (close == std::string::npos) break;
    const std::string s = script.substr(open + 1, close - open - 1);
    if (s.ends_with(".dat") || s.ends_with(".f32")) files.push_back(s);
    open = script.find('\'', close + 1);
  }
  return files;
}

// A data file with something to draw: a finite number outside the comment lines.
bool HasData(const fs::path& file) {
  if (file.extension() == ".f32") return fs::file_size(file) > 0;
  std::istringstream in(Slurp(file));
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    for (std::string f; fields >> f;) {
      char* end = nullptr;
      const double x = std::strtod(f.c_str(), &end);
      if (end != f.c_str() && *end == '\0' && std::isfinite(x)) return true;
    }
  }
  return false;
}

// Every panel of every drawn figure plots a file with data: broadcast's run 0 closed no pair, so
// loop_closures.png has decentralized's matrix only (two panels, not three).
TEST_F(HonestFigures, NoDrawnFigureHasAnEmptyPanel) {
  if (!FindProgram("gnuplot")) GTEST_SKIP() << "gnuplot is not installed";
  std::ostringstream log;
  const std::vector<fs::path> drawn = DrawTwoNetworks(log).pngs;
  ASSERT_FALSE(drawn.empty()) << log.str();
  for (const fs::path& png : drawn) {
    const std::string script = Slurp(dir_ / "figures" / "data" / (png.stem().string() + ".gp"));
    EXPECT_EQ(script.find("1/0"), std::string::npos) << png;  // a placeholder panel
    const std::vector<std::string> files = PlottedFiles(script);
    EXPECT_FALSE(files.empty()) << png;
    for (const std::string& f : files) EXPECT_TRUE(HasData(dir_ / "figures" / "data" / f)) << png << ": " << f;
  }
  const std::string closures = Slurp(dir_ / "figures" / "data" / "loop_closures-net0-point-to-point-10-mbit-s-2-ms.gp");
  EXPECT_NE(closures.find("set multiplot layout 1,2 "), std::string::npos) << closures;
  EXPECT_NE(closures.find("decentralized: first closure per pair"), std::string::npos) << closures;
  EXPECT_EQ(closures.find("broadcast: first closure per pair"), std::string::npos) << closures;
}

// Lesson 1 of docs/teaching.md: decentralized runs without a revisit in their frames. The notes
// say so, and loop_closures.png (nothing but zeros) is not drawn.
TEST_F(HonestFigures, ANoRevisitRunSaysWhyItsFiguresAreSkipped) {
  const std::vector<RunResult> rows = Rows({Net(0, "point_to_point", 1e7), Net(1, "shared_medium", 1e8)});
  std::string why;
  EXPECT_FALSE(WriteRelativeAucData(dir_, rows, &why));
  EXPECT_EQ(why, "2 decentralized runs, none with a relative AUC: no query had a revisit within the frames");
  EXPECT_FALSE(WriteRelativeAucData(dir_, {rows[1], rows[3]}, &why));  // broadcast only
  EXPECT_EQ(why, "no decentralized runs");
  if (!FindProgram("gnuplot")) GTEST_SKIP() << "gnuplot is not installed";
  WriteRunsCsv(dir_ / "runs.csv", rows);
  WriteRunFiles(rows, std::nullopt);
  std::ostringstream log;
  DrawFigures(dir_, testing_support::NetworkLabelsOf(rows), log);
  EXPECT_NE(log.str().find("relative_auc_balance.png skipped (2 decentralized runs, none with a relative AUC: no "
                           "query had a revisit within the frames)"),
            std::string::npos)
      << log.str();
  EXPECT_EQ(log.str().find("no decentralized runs"), std::string::npos) << log.str();
  // One note for both networks, not one per network.
  EXPECT_NE(log.str().find("loop_closures.png skipped (on all 2 networks: no run found an inter-robot loop closure "
                           "at n = 4)"),
            std::string::npos)
      << log.str();
  for (const std::string& png : Pngs()) EXPECT_EQ(png.find("loop_closures"), std::string::npos) << png;
}

// relative_auc_balance.png names the simulation's network (it is the paper protocol's otherwise).
TEST_F(HonestFigures, RelativeAucNamesTheSimulationsNetwork) {
  std::vector<RunResult> rows = Rows({Net(0, "point_to_point", 1e7), Net(1, "shared_medium", 1e8)});
  for (RunResult& r : rows) r.relative_auc = 0.9;
  ASSERT_TRUE(WriteRelativeAucData(dir_, rows));
  EXPECT_EQ(Slurp(dir_ / "relative_auc.protocol"), "sim\npoint-to-point 10 Mbit/s 2 ms\n");
  RunResult paper;
  paper.key = RunKey{.protocol = "paper", .strategy = "decentralized", .robots = 4, .run = 0, .network = {}};
  paper.relative_auc = 0.8;
  rows.push_back(paper);
  ASSERT_TRUE(WriteRelativeAucData(dir_, rows));
  EXPECT_EQ(Slurp(dir_ / "relative_auc.protocol"), "paper\n");
}

// confusion.f32 holds a float32 per pair of sampled frames: every 5th frame, or every k-th with
// k = ceil(frames / 1000) when that is larger, so the side stays at most 1000 (4 MB).
TEST(ConfusionData, TheMatrixSideIsCappedFromTheFrameCount) {
  EXPECT_EQ(ConfusionStep(4541, 5), 5);      // KITTI 00: 909 a side, as ever
  EXPECT_EQ(ConfusionStep(5000, 5), 5);      // exactly 1000 a side
  EXPECT_EQ(ConfusionStep(5001, 5), 6);      // 5001 / 5 would be 1001: every 6th, 834 a side
  EXPECT_EQ(ConfusionStep(22705, 5), 23);    // staggered 5 x 4541: 22.705 -> every 23rd, 988 a side
  const fs::path dir = dvpr::testing_support::FreshTestDir("figures_confusion");
  DescriptorMatrix frames(6001, 2);
  for (Eigen::Index i = 0; i < frames.rows(); ++i) frames.row(i) << static_cast<float>(i % 7), 1.0f;
  WriteConfusionData(dir, frames, 5);
  // 6001 frames: every ceil(6.001) = 7th, ceil(6001 / 7) = 858 a side, 858 x 858 x 4 bytes.
  EXPECT_EQ(Slurp(dir / "confusion.meta"), "858 7 6001\n");
  EXPECT_EQ(fs::file_size(dir / "confusion.f32"), 858u * 858u * 4u);
  EXPECT_LE(fs::file_size(dir / "confusion.f32"), 4'000'000u);
}

}  // namespace
}  // namespace dvpr
