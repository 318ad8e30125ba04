// The radio's figures (figures_radio.h): the numbers they plot, from hand-made connectivity.csv,
// runs.csv and queries.csv rows; and that they are drawn only where the results have them.
// Pixels are not tested.
#include <cmath>
#include <filesystem>
#include <sstream>

#include <gtest/gtest.h>

#include <cstdio>

#include "experiments/figures/figures.h"
#include "experiments/figures/figures_radio.h"
#include "experiments/figures/gnuplot_run.h"
#include "experiments/results/result_writers.h"
#include "tests/figures/figures_test_support.h"
#include "tests/test_support.h"

namespace dvpr {
namespace {

using dvpr::testing_support::Slurp;
namespace fs = std::filesystem;

// A radio of range `range_m` (NaN: log_distance).
NetworkLabel Radio(int variant, double range_m) {
  return NetworkLabel{.variant = variant, .model = "radio", .bandwidth_bps = 1e7, .latency_ms = 2, .loss = "none",
                      .propagation = std::isnan(range_m) ? "log_distance" : "range " + FormatDouble(range_m) + "m",
                      .range_m = range_m, .next_hop = "shortest_path"};
}

RunResult RadioRun(const std::string& strategy, int robots, int run, const NetworkLabel& net, double bytes_per_query,
              double latency_ms) {
  RunResult r;
  r.key = RunKey{.protocol = "sim", .strategy = strategy, .robots = robots, .run = run, .network = net};
  r.queries = 10;
  r.bytes_per_query = bytes_per_query;
  r.mean_latency_ms = latency_ms;
  return r;
}

class RadioFiguresTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = dvpr::testing_support::FreshTestDir("figures_radio");
    fs::create_directories(dir_ / "figures" / "data");
  }
  // Variant 0 point-to-point (no range), 1 radio of 100 m, 2 of 200 m, 3 log_distance.
  static std::vector<RunResult> Rows() {
    const NetworkLabel p2p{.variant = 0, .model = "point_to_point", .bandwidth_bps = 1e7, .latency_ms = 2,
                           .loss = "none"};
    return {RadioRun("decentralized", 4, 0, p2p, 900, 1),
            RadioRun("decentralized", 4, 0, Radio(1, 100), 1000, 30),
            RadioRun("decentralized", 4, 1, Radio(1, 100), 2000, 50),
            RadioRun("broadcast", 4, 0, Radio(1, 100), 3000, 70),
            RadioRun("decentralized", 4, 0, Radio(2, 200), 800, 4),
            RadioRun("broadcast", 4, 0, Radio(2, 200), 2500, 6),
            RadioRun("decentralized", 4, 0, Radio(3, kNotApplicable), 5, 5)};
  }
  fs::path dir_;
};

TEST_F(RadioFiguresTest, ConnectivityShowsTheFirstRunOfTheFirstStrategyPerVariant) {
  CsvTable t;
  t.header = {"protocol", "strategy", "robots", "run", "network_variant", "time_s", "pairs_in_range", "components",
              "largest_component", "mean_hops", "max_hops"};
  t.rows = {{"sim", "decentralized", "3", "0", "1", "0", "2", "1", "3", "1.3333333333333333", "2"},
            {"sim", "decentralized", "3", "0", "1", "0.1", "1", "2", "2", "1", "1"},
            {"sim", "decentralized", "3", "0", "2", "0", "3", "1", "3", "1", "1"},
            {"sim", "decentralized", "3", "1", "1", "0", "0", "3", "1", "0", "0"},   // run 1: not shown
            {"sim", "broadcast", "3", "0", "1", "0", "0", "3", "1", "0", "0"}};     // same run: not shown
  std::string why;
  const auto f = WriteConnectivityFigure(dir_, t, Rows(), why);
  ASSERT_TRUE(f.has_value()) << why;
  // 3 robots have 3 pairs: 2 of them in range is 66.67 %, 1 is 33.33 % (python3: 100.0 * 2 / 3.0
  // and 100.0 * 1 / 3.0); variant 2 has all 3.
  EXPECT_EQ(Slurp(dir_ / "conn_3.dat"),
            "# range 100m\n0 2 66.66666666666667 1\n0.1 1 33.333333333333336 2\n\n\n"
            "# range 200m\n0 3 100 1\n\n\n");
  EXPECT_NE(f->body.find("'range 200m'"), std::string::npos) << f->body;
  EXPECT_NE(f->body.find("% of the 3 pairs"), std::string::npos) << f->body;
  t.rows.clear();
  EXPECT_FALSE(WriteConnectivityFigure(dir_, t, Rows(), why).has_value());
}

TEST_F(RadioFiguresTest, RadioRangeMeansPerStrategyTeamAndRange) {
  CsvTable q;
  q.header = {"protocol", "strategy", "robots", "run", "robot", "latency_ns", "network_variant"};
  // Decentralized at 100 m: run 0 answers 1 of 2 queries (50 %), run 1 both (100 %): mean 75 %.
  q.rows = {{"sim", "decentralized", "4", "0", "0", "5", "1"}, {"sim", "decentralized", "4", "0", "1", "", "1"},
            {"sim", "decentralized", "4", "1", "0", "5", "1"}, {"sim", "decentralized", "4", "1", "1", "7", "1"},
            {"sim", "broadcast", "4", "0", "0", "", "2"},      {"sim", "broadcast", "4", "0", "1", "9", "2"},
            {"paper", "decentralized", "4", "0", "0", "", "1"}};  // not a simulated query
  std::string why;
  const auto f = WriteRadioRangeFigure(dir_, Rows(), q, why);
  ASSERT_TRUE(f.has_value()) << why;
  // Decentralized at 100 m: (1000 + 2000) / 2 bytes, (30 + 50) / 2 ms. Point-to-point and
  // log_distance have no range: not on this figure. Broadcast at 100 m has no query row: NaN.
  // These rows have no bytes by role: no share of query copies delivered (last column NaN).
  EXPECT_EQ(Slurp(dir_ / "radio_range.dat"),
            "# decentralized n = 4\n100 1500 75 40 NaN\n200 800 NaN 4 NaN\n\n\n"
            "# broadcast n = 4\n100 3000 NaN 70 NaN\n200 2500 50 6 NaN\n\n\n");
  EXPECT_NE(f->body.find("using 1:3 "), std::string::npos) << f->body;  // the answered share
  // Circled: the points that answered under 90 %, decentralized at 100 m (75 %) and broadcast at
  // 200 m (50 %); broadcast at 100 m has no share (NaN), so no circle.
  EXPECT_EQ(Slurp(dir_ / "radio_range_split.dat"), "100 1500 \"75%\"\n200 2500 \"50%\"\n");
  EXPECT_NE(f->body.find("circled: under 90 % answered: few bytes because the team is split"), std::string::npos)
      << f->body;
  // One range is no curve.
  std::vector<RunResult> one = Rows();
  one.erase(one.begin() + 4, one.begin() + 6);
  EXPECT_FALSE(WriteRadioRangeFigure(dir_, one, q, why).has_value());
  EXPECT_EQ(why, "needs radio variants of two or more ranges");
}

// Without queries.csv (radio_kitti00.yaml writes none) the middle panel draws the share of query
// copies delivered, from runs.csv's bytes by role, and no panel is left empty.
TEST_F(RadioFiguresTest, RadioRangeWithoutQueriesDrawsTheQueryCopiesDelivered) {
  std::vector<RunResult> rows = Rows();
  const auto delivered = [](RunResult& r, std::int64_t offered, std::int64_t arrived) {
    RunRoleBytes b;
    b.copies[0].wire = offered;
    b.copies[0].delivered_wire = arrived;
    r.roles = b;
  };
  delivered(rows[1], 1000, 200);   // decentralized 100 m run 0: 20 %
  delivered(rows[2], 1000, 400);   // run 1: 40 %, mean 30 %
  delivered(rows[3], 3000, 300);   // broadcast 100 m: 10 %
  delivered(rows[4], 1000, 1000);  // decentralized 200 m: 100 %
  delivered(rows[5], 3000, 2850);  // broadcast 200 m: 95 %
  std::string why;
  const auto f = WriteRadioRangeFigure(dir_, rows, CsvTable{}, why);
  ASSERT_TRUE(f.has_value()) << why;
  EXPECT_EQ(Slurp(dir_ / "radio_range.dat"),
            "# decentralized n = 4\n100 1500 NaN 40 30\n200 800 NaN 4 100\n\n\n"
            "# broadcast n = 4\n100 3000 NaN 70 10\n200 2500 NaN 6 95\n\n\n");
  EXPECT_EQ(Slurp(dir_ / "radio_range_split.dat"), "100 1500 \"30%\"\n100 3000 \"10%\"\n");
  EXPECT_NE(f->body.find("using 1:5 "), std::string::npos) << f->body;
  EXPECT_EQ(f->body.find("using 1:3 "), std::string::npos) << f->body;
  EXPECT_EQ(f->body.find("1/0"), std::string::npos) << f->body;  // no placeholder panel
  EXPECT_NE(f->body.find("circled: under 90 % of query copies delivered: few bytes because the team is split"),
            std::string::npos) << f->body;
}

// robots_in_range.png: the largest team's first run and first strategy, one panel per radio
// (variant 4 repeats variant 1's radio with another routing: not a panel of its own), each robot's
// count at each time with the time's components.
TEST_F(RadioFiguresTest, RobotsInRangeShowsEachRobotOfTheLargestTeamPerRadio) {
  CsvTable t;
  t.header = {"protocol", "strategy", "robots", "run", "network_variant", "time_s", "pairs_in_range", "components",
              "largest_component", "mean_hops", "max_hops", "robots_in_range"};
  t.rows = {{"sim", "decentralized", "2", "0", "1", "0", "1", "1", "2", "1", "1", "1 1"},     // n = 2: not shown
            {"sim", "decentralized", "3", "1", "1", "0", "2", "1", "3", "1.3333333333333333", "2", "1 2 1"},
            {"sim", "decentralized", "3", "1", "1", "0.1", "1", "2", "2", "1", "1", "1 1 0"},
            {"sim", "decentralized", "3", "1", "2", "0", "0", "3", "1", "0", "0", "0 0 0"},
            {"sim", "decentralized", "3", "1", "4", "0", "3", "1", "3", "1", "1", "2 2 2"},   // routing twin of 1
            {"sim", "decentralized", "3", "2", "1", "0", "0", "3", "1", "0", "0", "0 0 0"},   // run 2: not shown
            {"sim", "broadcast", "3", "1", "1", "0", "0", "3", "1", "0", "0", "0 0 0"}};      // same run
  std::vector<RunResult> rows = Rows();
  rows.push_back(RadioRun("decentralized", 3, 1, Radio(1, 100), 1, 1));
  rows.push_back(RadioRun("decentralized", 3, 1, Radio(4, 100), 1, 1));
  rows.back().key.network.next_hop = "link_state";
  std::string why;
  const auto f = WriteRobotsInRangeFigure(dir_, t, rows, why);
  ASSERT_TRUE(f.has_value()) << why;
  EXPECT_EQ(Slurp(dir_ / "in_range_0.dat"),
            "# range 100m: time_s robot robots_in_range\n0 0 1\n0 1 2\n0 2 1\n\n0.1 0 1\n0.1 1 1\n0.1 2 0\n\n"
            "\n# time_s components\n0 1\n0.1 2\n");
  EXPECT_EQ(Slurp(dir_ / "in_range_1.dat"),
            "# range 200m: time_s robot robots_in_range\n0 0 0\n0 1 0\n0 2 0\n\n\n# time_s components\n0 3\n");
  EXPECT_FALSE(fs::exists(dir_ / "in_range_2.dat"));  // variant 4: the same radio as variant 1
  EXPECT_NE(f->body.find("set multiplot layout 2,1"), std::string::npos) << f->body;
  EXPECT_NE(f->body.find("n = 3"), std::string::npos) << f->body;
  EXPECT_NE(f->body.find("set cbrange [0:2]"), std::string::npos) << f->body;
  // A count outside the team, or too few counts, is an error naming the file's line.
  t.rows[2][11] = "1 3 0";
  t.path = "connectivity.csv";
  EXPECT_THROW(
      {
        try {
          WriteRobotsInRangeFigure(dir_, t, rows, why);
        } catch (const std::runtime_error& e) {
          EXPECT_EQ(std::string(e.what()), "connectivity.csv: line 4: robots_in_range: expected counts from 0 to 2, got '3'");
          throw;
        }
      },
      std::runtime_error);
  t.rows[2][11] = "1 1";
  EXPECT_THROW(WriteRobotsInRangeFigure(dir_, t, rows, why), std::runtime_error);
  // Without the column (a connectivity.csv of an earlier dvpr) or rows: no figure.
  t.header.pop_back();
  EXPECT_FALSE(WriteRobotsInRangeFigure(dir_, t, rows, why).has_value());
}

// radio_hops.png: per radio variant of the largest team, each strategy's delivered copies by hops,
// summed over runs, as a share of that strategy's copies.
TEST_F(RadioFiguresTest, RadioHopsShareOfCopiesPerStrategyAndVariant) {
  CsvTable t;
  t.header = {"protocol", "strategy", "robots", "run", "network_variant", "delivered_by_hops"};
  t.rows = {{"sim", "decentralized", "4", "0", "1", "6 2"},   // run 0: 6 copies of 1 hop, 2 of 2
            {"sim", "decentralized", "4", "1", "1", "2 0 0 2"},  // run 1: sums 8 2 0 2 = 12
            {"sim", "broadcast", "4", "0", "1", "3 1"},
            {"sim", "broadcast", "4", "0", "2", ""},          // nothing delivered: NaN
            {"sim", "decentralized", "4", "0", "2", "5"},
            {"sim", "decentralized", "3", "0", "1", "9 9 9"},  // a smaller team: not shown
            {"sim", "bow_broadcast", "4", "0", "1", "1"}};    // another strategy: not shown
  std::string why;
  const auto f = WriteRadioHopsFigure(dir_, t, Rows(), why);
  ASSERT_TRUE(f.has_value()) << why;
  // Variant 1: decentralized 8, 2, 0, 2 of 12 (python3: 100 * 8 / 12 = 66.66666666666667,
  // 100 * 2 / 12 = 16.666666666666668); broadcast 3, 1 of 4 = 75 %, 25 %, then nothing.
  EXPECT_EQ(Slurp(dir_ / "hops_0.dat"),
            "# range 100m shortest_path: hops decentralized_percent broadcast_percent\n"
            "1 66.66666666666667 75\n2 16.666666666666668 25\n3 0 0\n4 16.666666666666668 0\n");
  EXPECT_EQ(Slurp(dir_ / "hops_1.dat"),
            "# range 200m shortest_path: hops decentralized_percent broadcast_percent\n1 100 NaN\n");
  EXPECT_NE(f->body.find("n = 4"), std::string::npos) << f->body;
  EXPECT_NE(f->body.find("set multiplot layout 1,2"), std::string::npos) << f->body;
  t.rows[0][5] = "6 -2";
  EXPECT_THROW(WriteRadioHopsFigure(dir_, t, Rows(), why), std::runtime_error);
  t.header.back() = "something_else";
  EXPECT_FALSE(WriteRadioHopsFigure(dir_, t, Rows(), why).has_value());
}

// A routing loop's copies make up to 64 transmissions: beyond 8 hop classes, 5 and more hops are
// binned (5-9, 10-19, 20-64) so that the axis' labels stay readable; shares on an axis that ends
// at 100 %, the legend above the panels.
TEST_F(RadioFiguresTest, RadioHopsBinsLongPathsAndKeepsItsLegendOffTheBars) {
  CsvTable t;
  t.header = {"protocol", "strategy", "robots", "run", "network_variant", "delivered_by_hops"};
  std::vector<std::string> hops(45, "0");
  hops[0] = "6";   // 1 hop
  hops[6] = "1";   // 7 hops
  hops[14] = "1";  // 15 hops
  hops[44] = "2";  // 45 hops
  std::string field;
  for (const std::string& h : hops) field += (field.empty() ? "" : " ") + h;
  t.rows = {{"sim", "decentralized", "4", "0", "1", field}, {"sim", "broadcast", "4", "0", "1", "4"}};
  std::string why;
  const auto f = WriteRadioHopsFigure(dir_, t, Rows(), why);
  ASSERT_TRUE(f.has_value()) << why;
  // Of 10 copies: 6 of 1 hop, then 1 in 5-9 (7 hops), 1 in 10-19 (15), 2 in 20-64 (45).
  EXPECT_EQ(Slurp(dir_ / "hops_0.dat"),
            "# range 100m shortest_path: hops decentralized_percent broadcast_percent\n"
            "1 60 100\n2 0 0\n3 0 0\n4 0 0\n5-9 10 0\n10-19 10 0\n20-64 20 0\n");
  EXPECT_NE(f->body.find("set yrange [0:100]"), std::string::npos) << f->body;
  const std::size_t key = f->body.find("set key at screen 0.5, screen ");
  ASSERT_NE(key, std::string::npos) << f->body;
  double key_y = 0, left = 0, right = 0, bottom = 0, top = 0;
  ASSERT_EQ(std::sscanf(f->body.c_str() + key, "set key at screen 0.5, screen %lf", &key_y), 1);
  const std::size_t m = f->body.find("margins ");
  ASSERT_NE(m, std::string::npos);
  ASSERT_EQ(std::sscanf(f->body.c_str() + m, "margins %lf, %lf, %lf, %lf", &left, &right, &bottom, &top), 4);
  // The key (one row of text in its box: about 25 pixels) hangs from key_y; the panels' titles
  // take the 30 pixels above their plot areas.
  EXPECT_GT(key_y - 25.0 / f->height, top + 30.0 / f->height) << f->body;
}

TEST_F(RadioFiguresTest, DrawnOnlyWhereTheResultsHaveThem) {
  if (!FindProgram("gnuplot")) GTEST_SKIP() << "gnuplot is not installed";
  WriteRunsCsv(dir_ / "runs.csv", Rows());
  std::ostringstream log;
  DrawFigures(dir_, dvpr::testing_support::NetworkLabelsOf(Rows()), log);
  EXPECT_TRUE(fs::exists(dir_ / "figures" / "radio_range.png")) << log.str();
  EXPECT_FALSE(fs::exists(dir_ / "figures" / "connectivity.png"));  // no connectivity.csv
  EXPECT_FALSE(fs::exists(dir_ / "figures" / "robots_in_range.png"));
  EXPECT_FALSE(fs::exists(dir_ / "figures" / "radio_hops.png"));       // no radio.csv
  EXPECT_EQ(log.str().find("connectivity"), std::string::npos) << log.str();  // and no "skipped" line
}

}  // namespace
}  // namespace dvpr
