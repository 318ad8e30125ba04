// Figures 7 and 8 (strategy_tradeoff.png, strategy_sweep.png): the numbers they plot, from a
// small hand-made set of runs.csv rows. Pixels are not tested.
#include <array>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "experiments/figures/figures.h"
#include "experiments/figures/gnuplot_run.h"
#include "experiments/results/result_writers.h"
#include "tests/descriptor_support.h"
#include "tests/test_support.h"

namespace dvpr {
namespace {

using dvpr::testing_support::Slurp;

namespace fs = std::filesystem;

RunResult Paper(const std::string& strategy, int robots, int run, double rel, double balance) {
  RunResult r;
  r.key = RunKey{.protocol = "paper", .strategy = strategy, .robots = robots, .run = run,
                 .network = {}};
  r.relative_auc = rel;
  r.worst_balance_ratio = balance;
  return r;
}

RunResult Sim(const std::string& strategy, int robots, int run, int variant, double bytes) {
  RunResult r;
  r.key = RunKey{.protocol = "sim", .strategy = strategy, .robots = robots, .run = run,
                 .network = NetworkLabel{.variant = variant,
                                         .model = variant == 0 ? "point_to_point" : "shared_medium",
                                         .bandwidth_bps = 1e7, .latency_ms = 2, .loss = "none"}};
  r.relative_auc = 0.5;  // differs from every paper value: must not leak into the paper columns
  r.worst_balance_ratio = 7;
  r.bytes_per_query = bytes;
  return r;
}

class StrategyFigures : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = dvpr::testing_support::FreshTestDir("figures");
  }
  // decentralized: n = 5 (1 run), 10 and 20 (2 runs each); broadcast (no static balance) and
  // sample_c4 at 10 only; sim rows at n = 10 on two network variants.
  static std::vector<RunResult> Rows() {
    return {Paper("decentralized", 5, 0, 0.9, 2.0),     Paper("decentralized", 10, 0, 0.8, 4.0),
            Paper("decentralized", 10, 1, 0.7, 5.0),    Paper("decentralized", 20, 0, 0.75, 9.0),
            Paper("decentralized", 20, 1, 0.65, 10.0),  Paper("broadcast", 10, 0, 1.0, kNotApplicable),
            Paper("sample_c4", 10, 0, 0.95, 1.25),      Sim("decentralized", 10, 0, 0, 17000),
            Sim("decentralized", 10, 1, 0, 18000),      Sim("decentralized", 10, 0, 1, 99999),
            Sim("broadcast", 10, 0, 0, 25000)};
  }
  fs::path dir_;
};

TEST_F(StrategyFigures, MeansMinMaxPerStrategyAndN) {
  const StrategyTable t = TabulateStrategies(Rows());
  EXPECT_EQ(t.accuracy_protocol, "paper");
  EXPECT_EQ(t.strategies, (std::vector<std::string>{"decentralized", "broadcast", "sample_c4"}));
  EXPECT_EQ(t.robots, (std::vector<int>{5, 10, 20}));
  EXPECT_EQ(t.bytes_variant, 0);
  EXPECT_EQ(t.bytes_network, "point-to-point 10 Mbit/s 2 ms");

  const StrategyStats* d10 = t.Find("decentralized", 10);
  ASSERT_NE(d10, nullptr);
  EXPECT_EQ(d10->relative_auc.runs, 2);  // paper rows only: the sim's 0.5 stays out
  EXPECT_DOUBLE_EQ(d10->relative_auc.mean, 0.75);
  EXPECT_DOUBLE_EQ(d10->relative_auc.min, 0.7);
  EXPECT_DOUBLE_EQ(d10->relative_auc.max, 0.8);
  EXPECT_DOUBLE_EQ(d10->worst_balance.mean, 4.5);
  EXPECT_EQ(d10->bytes_per_query.runs, 2);  // network variant 0 only: 99999 stays out
  EXPECT_DOUBLE_EQ(d10->bytes_per_query.mean, 17500);
  EXPECT_DOUBLE_EQ(d10->bytes_per_query.max, 18000);

  const StrategyStats* b10 = t.Find("broadcast", 10);
  ASSERT_NE(b10, nullptr);
  EXPECT_EQ(b10->worst_balance.runs, 0);
  EXPECT_TRUE(std::isnan(b10->worst_balance.mean));
  EXPECT_DOUBLE_EQ(b10->bytes_per_query.mean, 25000);
  EXPECT_EQ(t.Find("sample_c4", 20), nullptr);
  EXPECT_EQ(t.Find("decentralized", 5)->bytes_per_query.runs, 0);
}

// relative_auc_balance.png's band: per n, the mean's 95 % confidence interval over the paper
// protocol's decentralized runs, worked by hand: n = 10 has 0.8 and 0.7 (mean 0.75, s = 0.0707106781,
// half-width t(0.975, 1) = 12.706204736 times s / sqrt(2) = 0.6353102368); n = 20 has 0.75 and
// 0.65; n = 5 one run, no band (the mean on both sides). The balance at n = 10: 4 and 5, half-width
// 6.353102368.
TEST_F(StrategyFigures, RelativeAucBandIsTheMeansConfidenceInterval) {
  ASSERT_TRUE(WriteRelativeAucData(dir_, Rows()));
  const auto read = [&](const char* file) {
    std::ifstream in(dir_ / file);
    std::string header;
    std::getline(in, header);
    EXPECT_EQ(header, "# robots, mean - ci95, mean + ci95");
    std::vector<std::array<double, 3>> rows;
    for (std::array<double, 3> r{}; in >> r[0] >> r[1] >> r[2];) rows.push_back(r);
    return rows;
  };
  const auto auc = read("relative_auc_ci.dat");
  ASSERT_EQ(auc.size(), 3u);
  const double want[3][3] = {{5, 0.9, 0.9}, {10, 0.1146897632, 1.3853102368}, {20, 0.0646897632, 1.3353102368}};
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(auc[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)], want[i][j], 1e-9) << i << "," << j;
  }
  const auto balance = read("balance_ci.dat");
  ASSERT_EQ(balance.size(), 3u);
  EXPECT_NEAR(balance[1][1], 4.5 - 6.353102368, 1e-8);
  EXPECT_NEAR(balance[1][2], 4.5 + 6.353102368, 1e-8);
}

TEST_F(StrategyFigures, SimulationIsTheFallbackForAccuracy) {
  const StrategyTable t = TabulateStrategies(
      {Sim("decentralized", 10, 0, 1, 100), Sim("decentralized", 10, 0, 0, 200)});
  EXPECT_EQ(t.accuracy_protocol, "sim");
  EXPECT_EQ(t.bytes_variant, 0);
  EXPECT_EQ(t.Find("decentralized", 10)->relative_auc.runs, 1);  // first variant only
  EXPECT_DOUBLE_EQ(t.Find("decentralized", 10)->bytes_per_query.mean, 200);
}

TEST(ComparedRobots, TenAndTwentyElseTheTwoLargest) {
  EXPECT_EQ(ComparedRobots({2, 5, 10, 15, 20}), (std::vector<int>{10, 20}));
  EXPECT_EQ(ComparedRobots({10, 20, 30}), (std::vector<int>{10, 20}));
  EXPECT_EQ(ComparedRobots({5, 10, 15}), (std::vector<int>{10, 15}));
  EXPECT_EQ(ComparedRobots({25, 2, 15}), (std::vector<int>{15, 25}));
  EXPECT_EQ(ComparedRobots({10}), (std::vector<int>{10}));
}

TEST_F(StrategyFigures, TradeoffDataColumns) {
  ASSERT_TRUE(WriteStrategyTradeoffData(dir_, Rows()));
  // Per compared n (10, 20): relative AUC, worst balance, kB per query; mean, min, max each.
  std::istringstream dat(Slurp(dir_ / "strategy_tradeoff.dat"));
  std::string line;
  std::getline(dat, line);
  // Full precision, shortest form: (0.8 + 0.7) / 2 is 0.75, (0.75 + 0.65) / 2 is 0.7 in double.
  EXPECT_EQ(line, "0 0.75 0.7 0.8 4.5 4 5 17.5 17 18 0.7 0.65 0.75 9.5 9 10 NaN NaN NaN");
  std::getline(dat, line);
  EXPECT_EQ(line, "1 1 1 1 NaN NaN NaN 25 25 25 NaN NaN NaN NaN NaN NaN NaN NaN NaN");
  EXPECT_EQ(Slurp(dir_ / "strategy_tradeoff.names"), "decentralized\nbroadcast\nsample_c4\n");
  const std::string meta = Slurp(dir_ / "strategy_tradeoff.meta");
  // Rows without a value at either n get a "not measured" note: broadcast's static balance,
  // sample_c4's bytes (no sim rows).
  EXPECT_EQ(meta.rfind("robots 10 20\nmissing_0\nmissing_3 1\nmissing_6 2\nprotocol paper\n"
                       "network point-to-point 10 Mbit/s 2 ms\nruns 2\n", 0),
            0u) << meta;
  // One scatter label per strategy with both a balance and an AUC: broadcast has no balance.
  const std::string labels = Slurp(dir_ / "strategy_tradeoff_labels_0.txt");
  EXPECT_NE(labels.find(" decentralized\n"), std::string::npos) << labels;
  EXPECT_NE(labels.find(" sample_c4\n"), std::string::npos);
  EXPECT_EQ(labels.find("broadcast"), std::string::npos);
}

TEST_F(StrategyFigures, CoincidentStrategiesShareOneLabel) {
  ASSERT_TRUE(WriteStrategyTradeoffData(
      dir_, {Paper("lpt_c10", 20, 0, 0.654, 5.41), Paper("bounded_c10_0.25", 20, 0, 0.654, 5.41),
             Paper("decentralized", 20, 0, 0.785, 9.39)}));
  const std::string labels = Slurp(dir_ / "strategy_tradeoff_labels_0.txt");
  EXPECT_NE(labels.find(" lpt_c10, bounded_c10_0.25\n"), std::string::npos) << labels;
  EXPECT_NE(labels.find(" decentralized\n"), std::string::npos);
  EXPECT_FALSE(fs::exists(dir_ / "strategy_tradeoff_labels_1.txt"));  // one n only
}

TEST_F(StrategyFigures, SweepDataOneBlockPerStrategy) {
  ASSERT_TRUE(WriteStrategySweepData(dir_, Rows()));
  EXPECT_EQ(Slurp(dir_ / "strategy_sweep_auc.dat"),
            "# decentralized\n5 0.9\n10 0.75\n20 0.7\n\n\n"
            "# broadcast\n10 1\n\n\n# sample_c4\n10 0.95\n");
  EXPECT_EQ(Slurp(dir_ / "strategy_sweep_balance.dat"),
            "# decentralized\n5 2\n10 4.5\n20 9.5\n\n\n"
            "# broadcast\nNaN NaN\n\n\n# sample_c4\n10 1.25\n");
  EXPECT_EQ(Slurp(dir_ / "strategy_sweep_bytes.dat"),
            "# decentralized\n10 17.5\n\n\n# broadcast\n10 25\n\n\n"
            "# sample_c4\nNaN NaN\n");
  EXPECT_EQ(Slurp(dir_ / "strategy_sweep.titles"), "decentralized\nbroadcast\nsample_c4\n");
}

TEST_F(StrategyFigures, SweepNamesStrategiesWhoseBalanceLinesCoincide) {
  // replicate_* only add stores: same balance as decentralized at every n; lpt_c10 differs at 20.
  std::vector<RunResult> rows;
  for (const char* s : {"decentralized", "replicate_0.2", "lpt_c10", "replicate_0.5_r5"}) {
    const bool lpt = std::string(s) == "lpt_c10";
    rows.push_back(Paper(s, 10, 0, 0.8, 4.0));
    rows.push_back(Paper(s, 20, 0, 0.8, lpt ? 5.0 : 9.0));
  }
  ASSERT_TRUE(WriteStrategySweepData(dir_, rows));
  const std::string meta = Slurp(dir_ / "strategy_sweep.meta");
  EXPECT_NE(meta.find("\nsame_balance decentralized = replicate_0.2 = replicate_0.5_r5\n"),
            std::string::npos) << meta;
  EXPECT_EQ(meta.find("lpt_c10"), std::string::npos);
  // The script puts one name per line under the legend.
  EXPECT_NE(StrategySweepScript(dir_, dir_ / "x.png")
                .find("decentralized\\n    = replicate_0.2\\n    = replicate_0.5_r5\""),
            std::string::npos);
}

TEST_F(StrategyFigures, NothingWrittenWithoutData) {
  RunResult no_auc = Paper("decentralized", 10, 0, kNotApplicable, 2.0);
  EXPECT_FALSE(WriteStrategyTradeoffData(dir_, {no_auc}));
  EXPECT_FALSE(WriteStrategyTradeoffData(dir_, {}));
  // One n is enough for the comparison, not for the sweep.
  EXPECT_FALSE(WriteStrategySweepData(dir_, {Paper("decentralized", 10, 0, 0.8, 4.0)}));
  EXPECT_TRUE(fs::is_empty(dir_));
  EXPECT_TRUE(WriteStrategyTradeoffData(dir_, {Paper("decentralized", 10, 0, 0.8, 4.0)}));
}

TEST_F(StrategyFigures, DrawFiguresSaysWhyTheSweepIsSkipped) {
  if (!FindProgram("gnuplot")) {
    GTEST_SKIP() << "gnuplot is not installed";
  }
  WriteRunsCsv(dir_ / "runs.csv", {Paper("decentralized", 10, 0, 0.8, 4.0),
                                   Paper("sample_c4", 10, 0, 0.9, 1.2)});
  std::ostringstream log;
  const auto drawn = DrawFigures(dir_, {}, log);  // the paper protocol: no network variants
  EXPECT_NE(log.str().find("strategy_sweep.png skipped (needs a relative AUC at two or more n)"),
            std::string::npos) << log.str();
  EXPECT_TRUE(fs::exists(dir_ / "figures" / "strategy_tradeoff.png")) << log.str();
  EXPECT_FALSE(fs::exists(dir_ / "figures" / "strategy_sweep.png"));
}

}  // namespace
}  // namespace dvpr
