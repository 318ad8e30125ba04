// contention.png (experiments/figures/figures_contention.h) from hand-made runs.csv rows: each
// (strategy, medium) series is one line through the team sizes in order, each point labelled
// with its n, and the one legend sits below both panels, outside their plot areas. Pixels are not
// tested.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "experiments/figures/figures_contention.h"
#include "experiments/figures/figures_traffic.h"
#include "tests/test_support.h"

namespace dvpr {
namespace {

namespace fs = std::filesystem;

// A sim run of `robots` offering `bytes` wire bytes over 10 s, a share of them delivered.
RunResult SimRow(const std::string& strategy, int robots, const NetworkLabel& net, std::int64_t bytes,
              double delivered) {
  RunResult r;
  r.key = RunKey{.protocol = "sim", .strategy = strategy, .robots = robots, .run = 0, .network = net};
  r.queries = 100;
  r.duration_s = 10;
  r.mean_latency_ms = robots;
  RunRoleBytes b;
  b.copies[0].wire = bytes;
  b.copies[0].delivered_wire = static_cast<std::int64_t>(static_cast<double>(bytes) * delivered);
  r.roles = b;
  return r;
}

class ContentionFigure : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = testing_support::FreshTestDir("figures_contention");
    // The ideal bus and wifi; team sizes given out of order, and a saturated team of 8 that
    // offers less than the team of 4.
    const NetworkLabel bus{.variant = 0, .model = "shared_medium", .bandwidth_bps = 6e6, .latency_ms = 0.001,
                           .loss = "none"};
    const NetworkLabel wifi{.variant = 1, .model = "wifi", .bandwidth_bps = 6e6, .loss = "none"};
    rows_ = {SimRow("broadcast", 8, bus, 30'000, 0.5), SimRow("broadcast", 2, bus, 10'000, 1.0),
             SimRow("broadcast", 4, bus, 40'000, 0.9), SimRow("broadcast", 2, wifi, 10'000, 1.0),
             SimRow("broadcast", 4, wifi, 20'000, 0.2)};
  }
  fs::path dir_;
  std::vector<RunResult> rows_;
};

TEST_F(ContentionFigure, EachSeriesIsOneLineThroughTheTeamSizesInOrderEachLabelled) {
  const std::optional<FigureScript> f = WriteContentionFigure(dir_, TabulateTraffic(rows_));
  ASSERT_TRUE(f.has_value());
  // Offered: bytes x 8 / 10 s; delivered share in %; the 7th column is n, ascending, also when a
  // bigger team offers less (8 robots: 0.024 Mbit/s after 4 robots' 0.032).
  std::istringstream dat(testing_support::Slurp(dir_ / "contention.dat"));
  std::vector<std::string> titles;
  std::vector<std::vector<std::vector<double>>> blocks;
  for (std::string line; std::getline(dat, line);) {
    if (line.rfind("# ", 0) == 0) {
      titles.push_back(line.substr(2));
      blocks.emplace_back();
    } else if (!line.empty()) {
      std::istringstream fields(line);
      std::vector<double> row;
      for (double v; fields >> v;) row.push_back(v);
      ASSERT_EQ(row.size(), 7u) << line;
      blocks.back().push_back(row);
    }
  }
  EXPECT_EQ(titles, (std::vector<std::string>{"broadcast, shared medium 6 Mbit/s 1 us", "broadcast, wifi 6 Mbit/s"}));
  ASSERT_EQ(blocks.size(), 2u);
  const std::vector<std::vector<double>> bus = {{0.008, 100, 2}, {0.032, 90, 4}, {0.024, 50, 8}};
  const std::vector<std::vector<double>> wifi = {{0.008, 100, 2}, {0.016, 20, 4}};
  for (std::size_t b = 0; b < 2; ++b) {
    const std::vector<std::vector<double>>& want = b == 0 ? bus : wifi;
    ASSERT_EQ(blocks[b].size(), want.size());
    for (std::size_t i = 0; i < want.size(); ++i) {
      EXPECT_NEAR(blocks[b][i][0], want[i][0], 1e-12);
      EXPECT_NEAR(blocks[b][i][1], want[i][1], 1e-9);
      EXPECT_EQ(blocks[b][i][6], want[i][2]);
    }
  }
  // A line with its bars per series, and the n of each point as a label beside it.
  for (const std::string part : {"index 0 using 1:2:4:5 with xyerrorlines", "index 1 using 1:2:4:5 with xyerrorlines",
                                 "index 0 using 1:3:4:6 with xyerrorlines", "index 0 using 1:2:(sprintf('%d', $7)) with labels",
                                 "index 1 using 1:3:(sprintf('%d', $7)) with labels"}) {
    EXPECT_NE(f->body.find(part), std::string::npos) << part << "\n" << f->body;
  }
  EXPECT_EQ(f->body.find("with xyerrorbars"), std::string::npos);  // no unconnected points
  // Each medium its own dash: the bus dash 1, wifi dash 2.
  EXPECT_NE(f->body.find("dt 1 pt"), std::string::npos);
  EXPECT_NE(f->body.find("dt 2 pt"), std::string::npos);
}

TEST_F(ContentionFigure, TheOneLegendIsBelowThePlotAreas) {
  const std::optional<FigureScript> f = WriteContentionFigure(dir_, TabulateTraffic(rows_));
  ASSERT_TRUE(f.has_value());
  // The panels' bottom margin (screen fraction) and the key's screen position.
  double left = 0, right = 0, bottom = 0, top = 0, key_x = 0, key_y = 0;
  const std::size_t m = f->body.find("margins ");
  ASSERT_NE(m, std::string::npos);
  ASSERT_EQ(std::sscanf(f->body.c_str() + m, "margins %lf, %lf, %lf, %lf", &left, &right, &bottom, &top), 4);
  const std::size_t k = f->body.find("set key at screen ");
  ASSERT_NE(k, std::string::npos);
  ASSERT_EQ(std::sscanf(f->body.c_str() + k, "set key at screen %lf, screen %lf", &key_x, &key_y), 2);
  EXPECT_NE(f->body.find("center bottom", k), std::string::npos);
  // Its two rows of 10-point text (about 0.05 of a 760-pixel figure) end below the panels' bottom
  // margin, which leaves room for the x axis' tics and label.
  EXPECT_LT(key_y + 0.05, bottom - 0.06);
  EXPECT_EQ(f->body.find("set key at", k + 1), std::string::npos);  // no second legend
  EXPECT_NE(f->body.find("unset key"), std::string::npos);       // the right panel draws none
  EXPECT_NE(f->body.find("set yrange [0:100]"), std::string::npos);  // a share ends at 100 %
}

TEST_F(ContentionFigure, NotDrawnWithoutAContendingMedium) {
  std::vector<RunResult> bus_only;
  for (const RunResult& r : rows_) {
    if (r.key.network.model == "shared_medium") bus_only.push_back(r);
  }
  EXPECT_FALSE(WriteContentionFigure(dir_, TabulateTraffic(bus_only)).has_value());
}

}  // namespace
}  // namespace dvpr
