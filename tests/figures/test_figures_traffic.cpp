// The traffic figures (figures_traffic.h): the numbers they plot, from hand-made runs.csv rows
// with bytes by role, and which figures are drawn for which configs. Pixels are not tested.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "experiments/figures/figures.h"
#include "experiments/figures/figures_traffic.h"
#include "experiments/figures/gnuplot_run.h"
#include "experiments/results/result_writers.h"
#include "tests/figures/figures_test_support.h"
#include "tests/test_support.h"

namespace dvpr {
namespace {

using dvpr::testing_support::Slurp;
namespace fs = std::filesystem;

using testing_support::Net;

// A sim run with `query` and `reply` copy wire bytes, 1000 more of verification requests, 100
// queries over 10 s, `delivered` of the copies' wire delivered.
RunResult SimRun(const std::string& strategy, int robots, int run, const NetworkLabel& net, std::int64_t query,
              std::int64_t reply, double delivered = 1.0) {
  RunResult r;
  r.key = RunKey{.protocol = "sim", .strategy = strategy, .robots = robots, .run = run, .network = net};
  r.queries = 100;
  r.duration_s = 10;
  r.mean_latency_ms = 5;
  RunRoleBytes b;
  b.copies[0].wire = query;
  b.copies[1].wire = reply;
  b.copies[2].wire = 1000;
  for (CopyBytes& c : b.copies) c.delivered_wire = static_cast<std::int64_t>(static_cast<double>(c.wire) * delivered);
  r.roles = b;
  return r;
}

class TrafficFigures : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = dvpr::testing_support::FreshTestDir("figures_traffic");
    fs::create_directories(dir_ / "figures" / "data");
  }
  // Two networks: point-to-point 10 Mbit/s (variant 0), shared medium 100 Mbit/s (variant 1).
  static std::vector<RunResult> Rows() {
    const NetworkLabel p2p = Net(0, "point_to_point", 1e7), shared = Net(1, "shared_medium", 1e8);
    return {SimRun("decentralized", 4, 0, p2p, 600, 100), SimRun("decentralized", 4, 1, p2p, 500, 100),
            SimRun("broadcast", 4, 0, p2p, 1800, 300),    SimRun("decentralized", 4, 0, shared, 600, 100, 0.5),
            SimRun("broadcast", 4, 0, shared, 1800, 300, 0.25)};
  }
  fs::path dir_;
};

TEST_F(TrafficFigures, MeansPerStrategyNetworkAndTeam) {
  const TrafficTable t = TabulateTraffic(Rows());
  ASSERT_EQ(t.networks.size(), 2u);
  EXPECT_EQ(t.strategies, (std::vector<std::string>{"decentralized", "broadcast"}));
  const TrafficCell* d = t.Find("decentralized", 0, 4);
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->runs, 2);
  // Runs: (600 + 100) / 100 = 7 and (500 + 100) / 100 = 6 bytes per query: mean 6.5.
  EXPECT_DOUBLE_EQ(d->pr_bytes_per_query, 6.5);
  EXPECT_DOUBLE_EQ(d->role_bytes_per_query[0], 5.5);
  EXPECT_DOUBLE_EQ(d->role_bytes_per_query[2], 10.0);
  // Offered: (700 or 600) + 1000 bytes x 8 / 10 s = 1360 or 1280 bit/s: mean 1.32e-3 Mbit/s.
  EXPECT_DOUBLE_EQ(d->offered_mbps, 1.32e-3);
  const TrafficCell* b = t.Find("broadcast", 1, 4);
  ASSERT_NE(b, nullptr);
  EXPECT_DOUBLE_EQ(b->delivered_mbps, b->offered_mbps / 4);  // 3100 x 8 / 10 = 2480 bit/s, a quarter delivered
  // The law is shown on point-to-point links, the largest bandwidth among them.
  EXPECT_EQ(t.ShownVariant(), 0);
}

TEST_F(TrafficFigures, PlaceRecognitionRatioOnEveryNetwork) {
  const TrafficTable t = TabulateTraffic(Rows());
  std::string why;
  const auto f = WritePlaceRecognitionFigure(dir_, t, why);
  ASSERT_TRUE(f.has_value()) << why;
  // Point-to-point: 21 / 6.5 = 3.230769230769231 (python3 agrees); its runs: only run 0 has both
  // strategies, 21 / 7 = 3, so the bar is [3, 3]. Shared medium: 21 / 7 = 3.
  EXPECT_EQ(Slurp(dir_ / "pr_ratio.dat"),
            "# point-to-point 10 Mbit/s 2 ms\n4 3.230769230769231 3 3\n\n\n"
            "# shared medium 100 Mbit/s 2 ms\n4 3 3 3\n\n\n");
  // x, mean, 95 % half-width: decentralized's runs 7 and 6 bytes a query have std sqrt(1/2), and
  // t(0.975, 1) = tan(0.475 pi) (one degree of freedom is the Cauchy law), so the half-width is
  // tan(0.475 pi) sqrt(1/2) / sqrt(2) = 6.3531023680873...; broadcast has one run: 0.
  std::istringstream bytes(Slurp(dir_ / "pr_bytes.dat"));
  std::string line;
  std::vector<std::string> lines;
  while (std::getline(bytes, line)) lines.push_back(line);
  ASSERT_EQ(lines.size(), 12u);
  EXPECT_EQ(lines[0], "# decentralized");
  std::istringstream first(lines[1]);
  double n = 0, mean = 0, half = 0;
  first >> n >> mean >> half;
  EXPECT_EQ(n, 4);
  EXPECT_EQ(mean, 6.5);
  EXPECT_NEAR(half, std::tan(0.475 * std::numbers::pi) * 0.5, 1e-12);
  EXPECT_EQ(lines[4], "# broadcast");
  EXPECT_EQ(lines[5], "4 21 0");
  EXPECT_EQ(lines[8], "# n - 1 law");
  EXPECT_EQ(lines[9], "4 19.5");
  EXPECT_NE(f->body.find("broadcast / decentralized = 3.2"), std::string::npos) << f->body;
  EXPECT_NE(f->body.find("bars: its 95 % confidence interval"), std::string::npos) << f->body;
  EXPECT_NE(f->body.find("bars: lowest and highest run"), std::string::npos) << f->body;
}

// Every mean the traffic figures draw carries the half-width of its 95 % confidence interval.
TEST_F(TrafficFigures, EachMeanHasItsConfidenceInterval) {
  const TrafficTable t = TabulateTraffic(Rows());
  const double t1 = std::tan(0.475 * std::numbers::pi);  // t(0.975, 1)
  const TrafficCell* d = t.Find("decentralized", 0, 4);
  ASSERT_NE(d, nullptr);
  // Two runs a and b: std |a - b| / sqrt(2), half-width t1 |a - b| / 2.
  EXPECT_NEAR(d->pr_bytes_ci95, t1 * 0.5, 1e-12);          // 7 and 6 bytes a query
  EXPECT_NEAR(d->total_bytes_ci95, t1 * 0.5, 1e-12);       // 17 and 16 bytes a query
  EXPECT_NEAR(d->offered_ci95, t1 * 0.04e-3, 1e-15);       // 1.36e-3 and 1.28e-3 Mbit/s
  EXPECT_NEAR(d->delivered_ci95, t1 * 0.04e-3, 1e-15);     // all delivered
  EXPECT_EQ(d->latency_ci95, 0.0);                         // 5 ms both
  EXPECT_EQ(d->pr_bytes_by_run, (std::map<int, double>{{0, 7.0}, {1, 6.0}}));
  const TrafficCell* b = t.Find("broadcast", 0, 4);
  ASSERT_NE(b, nullptr);
  EXPECT_EQ(b->pr_bytes_ci95, 0.0);  // one run: no spread to draw
  // The stacked bars' data ends with the total and its half-width.
  std::string why;
  ASSERT_TRUE(WriteRoleFigure(dir_, t, why).has_value()) << why;
  std::istringstream roles(Slurp(dir_ / "roles_0.dat"));
  std::vector<double> fields;
  for (double x = 0; roles >> x;) fields.push_back(x);
  // n, query 5.5, reply 1, verify_request 10, total 16.5, half-width.
  ASSERT_EQ(fields.size(), 6u);
  EXPECT_EQ(fields[4], 16.5);
  EXPECT_NEAR(fields[5], t1 * 0.5, 1e-12);
}

TEST_F(TrafficFigures, SaturatedPointsAreMarked) {
  const TrafficTable t = TabulateTraffic(Rows());
  std::string why;
  const std::optional<FigureScript> f = WriteSaturationFigure(dir_, t, why);
  ASSERT_TRUE(f.has_value()) << why;
  EXPECT_EQ(Slurp(dir_ / "saturated.dat"), "100 5 \"50% delivered\"\n100 5 \"25% delivered\"\n");
  // The reference line is a function (the whole axis) drawn after the data of its panel, so it
  // is never hidden under them.
  const std::size_t reference = f->body.find("x with lines");
  ASSERT_NE(reference, std::string::npos) << f->body;
  const std::size_t panel_end = f->body.find('\n', reference);
  EXPECT_EQ(f->body.rfind("'offered.dat' index", panel_end), f->body.rfind("'offered.dat' index", reference));
  EXPECT_LT(f->body.rfind("'offered.dat' index", reference), reference);
  // Without a shared medium there is nothing to show.
  std::vector<RunResult> p2p = Rows();
  p2p.resize(3);
  EXPECT_FALSE(WriteSaturationFigure(dir_, TabulateTraffic(p2p), why).has_value());
  EXPECT_EQ(why, "needs protocol sim on a shared_medium network");
}

TEST_F(TrafficFigures, RobotLoadMarksTheBusiestRobotAndTheFairShare) {
  CsvTable per_robot;
  per_robot.header = {"protocol", "strategy", "robots", "run", "robot", "queries_received", "network_variant"};
  const int served[4] = {10, 70, 10, 10};
  for (int r = 0; r < 4; ++r) {
    per_robot.rows.push_back({"sim", "decentralized", "4", "0", std::to_string(r), std::to_string(served[r]), "0"});
  }
  per_robot.rows.push_back({"sim", "decentralized", "4", "1", "1", "999", "0"});  // another run: not shown
  std::string why;
  const auto f = WriteRobotLoadFigure(dir_, TabulateTraffic(Rows()), per_robot, why);
  ASSERT_TRUE(f.has_value()) << why;
  EXPECT_EQ(Slurp(dir_ / "load_0.dat"), "0 10\n1 70\n2 10\n3 10\n\n\n1 70\n");
  // Fair share 100 / 4 = 25; the busiest serves 70 = 2.8 times it.
  EXPECT_NE(f->body.find("busiest: robot 1, 2.8 x fair share"), std::string::npos) << f->body;
  EXPECT_NE(f->body.find("fair share (all searches / n = 25)"), std::string::npos);
}

// Two panels are compared bar for bar: the balanced strategy's (at most 20 searches a robot) is
// drawn on the paper method's scale (70 x 1.18 = 82.6), not on its own.
TEST_F(TrafficFigures, RobotLoadPanelsShareOneScale) {
  CsvTable per_robot;
  per_robot.header = {"protocol", "strategy", "robots", "run", "robot", "queries_received", "network_variant"};
  const int decentralized[4] = {10, 70, 10, 10};
  const int balanced[4] = {20, 20, 20, 20};
  for (int r = 0; r < 4; ++r) {
    per_robot.rows.push_back({"sim", "decentralized", "4", "0", std::to_string(r), std::to_string(decentralized[r]), "0"});
    per_robot.rows.push_back({"sim", "bounded_c10", "4", "0", std::to_string(r), std::to_string(balanced[r]), "0"});
  }
  std::vector<RunResult> rows = Rows();
  rows.push_back(SimRun("bounded_c10", 4, 0, rows.front().key.network, 700, 100));
  std::string why;
  const auto f = WriteRobotLoadFigure(dir_, TabulateTraffic(rows), per_robot, why);
  ASSERT_TRUE(f.has_value()) << why;
  std::vector<std::string> ranges;
  for (std::size_t at = f->body.find("set yrange"); at != std::string::npos; at = f->body.find("set yrange", at + 1)) {
    ranges.push_back(f->body.substr(at, f->body.find('\n', at) - at));
  }
  EXPECT_EQ(ranges, (std::vector<std::string>{"set yrange [0:82.6]", "set yrange [0:82.6]"})) << f->body;
  EXPECT_NE(f->body.find("set title 'bounded_c10'"), std::string::npos) << f->body;
}

// The robot id is the busiest robot's label position in the script, and src x dst indexes the
// traffic matrix: anything but a robot of the team is refused, naming file, line and column.
TEST_F(TrafficFigures, RobotIdsOutsideTheTeamAreRefused) {
  CsvTable per_robot;
  per_robot.path = "per_robot.csv";
  per_robot.header = {"protocol", "strategy", "robots", "run", "robot", "queries_received", "network_variant"};
  per_robot.rows = {{"sim", "decentralized", "4", "0", "0", "10", "0"},
                    {"sim", "decentralized", "4", "0", "1; system('touch x')", "70", "0"}};
  std::string why;
  try {
    WriteRobotLoadFigure(dir_, TabulateTraffic(Rows()), per_robot, why);
    ADD_FAILURE() << "accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()),
              "per_robot.csv: line 3: robot: expected an integer from 0 to 3, got '1; system('touch x')'");
  }
  CsvTable links;
  links.path = "links.csv";
  links.header = {"protocol", "strategy", "robots", "run", "src", "dst", "wire_bytes", "network_variant"};
  links.rows = {{"sim", "decentralized", "4", "0", "0", "4", "100", "0"}};
  try {
    WriteMatrixFigure(dir_, TabulateTraffic(Rows()), links, why);
    ADD_FAILURE() << "accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "links.csv: line 2: dst: expected an integer from 0 to 3, got '4'");
  }
  links.rows = {{"sim", "decentralized", "4", "0", "0", "1", "-5", "0"}};
  EXPECT_THROW(WriteMatrixFigure(dir_, TabulateTraffic(Rows()), links, why), std::runtime_error);
}

// loop_closures.png's numbers, worked by hand: decentralized at n = 3 (3 pairs), two runs of 30 s.
// Run 0 closes pair (0, 1) at 10 s and (1, 2) at 20 s, run 1 pair (0, 1) at 15 s. The share of
// pairs closed steps at 10 s (runs 1/3 and 0: mean 1/6), 15 s (1/3 and 1/3) and 20 s (2/3 and
// 1/3: mean 1/2, lowest 1/3, highest 2/3); run 0's matrix is symmetric, blank (NaN) elsewhere.
TEST_F(TrafficFigures, LoopClosuresByHand) {
  const NetworkLabel p2p = Net(0, "point_to_point", 1e7);
  std::vector<RunResult> rows = {SimRun("decentralized", 3, 0, p2p, 600, 100),
                                 SimRun("decentralized", 3, 1, p2p, 600, 100)};
  for (RunResult& r : rows) r.duration_s = 30;
  const auto pair = [&](int run, int a, int b, std::optional<std::int64_t> ns) {
    ClosurePairRow r{rows[0].key, a, b, ns};
    r.key.run = run;
    return r;
  };
  std::string csv = std::string(kClosurePairsHeader) + "\n";
  for (const ClosurePairRow& r : {pair(0, 0, 1, 10'000'000'000), pair(0, 0, 2, std::nullopt),
                                  pair(0, 1, 2, 20'000'000'000), pair(1, 0, 1, 15'000'000'000),
                                  pair(1, 0, 2, std::nullopt), pair(1, 1, 2, std::nullopt)}) {
    csv += CsvRow(r) + "\n";
  }
  std::ofstream(dir_ / "closure_pairs.csv") << csv;
  std::string why;
  const auto f = WriteClosureFigure(dir_, TabulateTraffic(rows), ReadCsvTable(dir_ / "closure_pairs.csv"), why);
  ASSERT_TRUE(f.has_value()) << why;
  EXPECT_EQ(Slurp(dir_ / "closures.dat"),
            "# decentralized\n"
            "0 0 0 0\n"
            "10 0 0 0\n10 0.16666666666666666 0 0.3333333333333333\n"
            "15 0.16666666666666666 0 0.3333333333333333\n15 0.3333333333333333 0.3333333333333333 0.3333333333333333\n"
            "20 0.3333333333333333 0.3333333333333333 0.3333333333333333\n20 0.5 0.3333333333333333 0.6666666666666666\n"
            "30 0.5 0.3333333333333333 0.6666666666666666\n\n\n");
  EXPECT_EQ(Slurp(dir_ / "closure_matrix_0.dat"), "NaN 10 NaN\n10 NaN 20\nNaN 20 NaN\n");
  EXPECT_NE(f->body.find("line: mean over runs, band: lowest to highest run"), std::string::npos) << f->body;
  // Without closure_pairs.csv (the static protocol only) there is nothing to draw.
  EXPECT_FALSE(WriteClosureFigure(dir_, TabulateTraffic(rows), CsvTable{}, why).has_value());
  EXPECT_EQ(why, "needs closure_pairs.csv");
}

// closure_pairs.csv's robots index the first-closure matrix: a robot outside the team is refused.
TEST_F(TrafficFigures, ClosurePairRobotsOutsideTheTeamAreRefused) {
  const NetworkLabel p2p = Net(0, "point_to_point", 1e7);
  CsvTable pairs;
  pairs.path = "closure_pairs.csv";
  pairs.header = {"protocol", "strategy", "robots", "run", "robot_a", "robot_b", "first_closure_ns", "network_variant"};
  pairs.rows = {{"sim", "decentralized", "3", "0", "0", "3", "100", "0"}};
  std::string why;
  try {
    WriteClosureFigure(dir_, TabulateTraffic({SimRun("decentralized", 3, 0, p2p, 600, 100)}), pairs, why);
    ADD_FAILURE() << "accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "closure_pairs.csv: line 2: robot_b: expected an integer from 0 to 2, got '3'");
  }
}

TEST_F(TrafficFigures, StrategyFiguresOnlyBeyondThePapersTwo) {
  if (!FindProgram("gnuplot")) GTEST_SKIP() << "gnuplot is not installed";
  WriteRunsCsv(dir_ / "runs.csv", Rows());
  std::ostringstream log;
  DrawFigures(dir_, testing_support::NetworkLabelsOf(Rows()), log);
  EXPECT_NE(log.str().find("strategy_tradeoff.png skipped (only the paper's two strategies are configured)"),
            std::string::npos) << log.str();
  EXPECT_TRUE(fs::exists(dir_ / "figures" / "place_recognition_bytes.png")) << log.str();
  // Two networks: one traffic_by_role figure each (test_figures_honest.cpp has the whole set).
  EXPECT_TRUE(fs::exists(dir_ / "figures" / "traffic_by_role-net0-point-to-point-10-mbit-s-2-ms.png")) << log.str();
  EXPECT_TRUE(fs::exists(dir_ / "figures" / "traffic_by_role-net1-shared-medium-100-mbit-s-2-ms.png")) << log.str();
  EXPECT_TRUE(fs::exists(dir_ / "figures" / "saturation.png")) << log.str();
  // No per_robot.csv here, nor closure_pairs.csv: one note each, for both networks.
  EXPECT_NE(log.str().find("robot_load.png skipped (on all 2 networks: needs per_robot.csv)"), std::string::npos)
      << log.str();
  EXPECT_NE(log.str().find("loop_closures.png skipped (on all 2 networks: needs closure_pairs.csv)"),
            std::string::npos) << log.str();
}

}  // namespace
}  // namespace dvpr
