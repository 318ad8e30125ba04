// The summary table `dvpr run` prints (PrintSummaryTable): its columns stay aligned whatever the
// numbers (issue 48: "6.71+-21.38" with runs=2 pushed a row two characters past its header), and
// a relative AUC over a reference that found almost nothing is marked (issue 48: the contention
// run's wifi rows printed 8.254 over a broadcast that delivered almost nothing, without a word).
#include <gtest/gtest.h>

#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "experiments/app/experiment.h"

namespace dvpr {
namespace {

RunResult Row(int run, double worst_balance) {
  RunResult r;
  r.key = RunKey{.protocol = "paper", .strategy = "decentralized", .robots = 3, .run = run, .network = {}};
  r.auc = 0.5;
  r.relative_auc = 0.9;
  r.worst_balance_ratio = worst_balance;
  return r;
}

std::vector<std::string> Lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// One run: the widths the table always had (the label column 34, then 6, 5, 13, 13, 11, 15, 15
// right-aligned, one space apart).
TEST(SummaryTable, OneRunKeepsTheUsualWidths) {
  std::ostringstream out;
  PrintSummaryTable({Row(0, 1.5)}, out);
  const std::vector<std::string> lines = Lines(out.str());
  ASSERT_EQ(lines.size(), 2U);
  EXPECT_EQ(lines[0], "protocol strategy                  robots  runs           auc       rel_auc   worst_bal "
                      "    bytes/query      latency_ms");
  EXPECT_EQ(lines[1], "paper decentralized                     3     1         0.500         0.900        1.50 "
                      "              -               -");
}

// Two runs with worst balances 1 and 21: mean 11, standard deviation sqrt(200) = 14.142, and the
// 95 % half-width t(0.975, 1) x 14.142 / sqrt(2) = 12.706 x 10 = 127.06. "11.00+-127.06" is 13
// characters, 2 more than the column's usual 11: the column widens, in every line.
TEST(SummaryTable, AWideCellWidensItsColumnInEveryLine) {
  std::ostringstream out;
  PrintSummaryTable({Row(0, 1.0), Row(1, 21.0)}, out);
  const std::vector<std::string> lines = Lines(out.str());
  ASSERT_EQ(lines.size(), 2U);
  const std::size_t cell = lines[1].find("11.00+-127.06");
  ASSERT_NE(cell, std::string::npos) << lines[1];
  const std::size_t header = lines[0].find("worst_bal");
  ASSERT_NE(header, std::string::npos);
  EXPECT_EQ(header + std::string("worst_bal").size(), cell + std::string("11.00+-127.06").size());
  EXPECT_EQ(lines[0].size(), lines[1].size());
  EXPECT_EQ(lines[1].substr(cell - 1, 1), " ");  // still one space from the column before
}

// A run of `strategy` with its AUC and its reference's (relative = auc / reference).
RunResult Referenced(const std::string& protocol, const std::string& strategy, int run, double auc, double reference) {
  RunResult r;
  r.key = RunKey{.protocol = protocol, .strategy = strategy, .robots = 4, .run = run, .network = {}};
  r.auc = auc;
  r.auc_reference = reference;
  r.relative_auc = auc / reference;
  return r;
}

// The right edge of the rel_auc cell: that of its header, the '*' included.
void ExpectRelAucCell(const std::vector<std::string>& lines, std::size_t line, const std::string& cell) {
  const std::size_t header = lines[0].find("rel_auc");
  ASSERT_NE(header, std::string::npos);
  const std::size_t at = lines[line].find(" " + cell + " ");
  ASSERT_NE(at, std::string::npos) << lines[line];
  EXPECT_EQ(at + 1 + cell.size(), header + std::string("rel_auc").size()) << lines[line];
}

// A broadcast that found almost nothing (AUC 0.02, under the 0.1 of kLowReferenceAuc): the
// decentralized run's 0.1 over it is 5.000, its own ratio 1.000; both cells are marked and one
// line under the table gives the reference's AUC and the threshold. The paper row's reference
// (0.6: 0.5 / 0.6 = 0.833) is not marked. A group is marked when any of its runs is: the two runs
// of the sim decentralized group at 8 robots over references 0.3 and 0.01 (0.15 / 0.3 = 0.5 and
// 0.03 / 0.01 = 3: mean 1.75) are, and the footnote's lowest reference is then 0.010.
TEST(SummaryTable, ARelativeAucOverAReferenceThatFoundAlmostNothingIsMarked) {
  std::vector<RunResult> rows{Referenced("sim", "decentralized", 0, 0.1, 0.02),
                              Referenced("sim", "broadcast", 0, 0.02, 0.02),
                              Referenced("paper", "decentralized", 0, 0.5, 0.6)};
  std::ostringstream out;
  PrintSummaryTable(rows, out);
  std::vector<std::string> lines = Lines(out.str());
  ASSERT_EQ(lines.size(), 5U) << out.str();
  ExpectRelAucCell(lines, 1, "5.000*");
  ExpectRelAucCell(lines, 2, "1.000*");
  ExpectRelAucCell(lines, 3, "0.833");
  EXPECT_EQ(lines[3].find('*'), std::string::npos);
  EXPECT_EQ(lines[4], "* rel_auc over a reference AUC below 0.10 in a run (lowest 0.020, runs.csv auc_reference): its "
                      "reference found almost nothing, the ratio says little (docs/outputs.md)");

  RunResult high = Referenced("sim", "decentralized", 0, 0.15, 0.3), low = Referenced("sim", "decentralized", 1, 0.03, 0.01);
  high.key.robots = low.key.robots = 8;
  std::ostringstream two;
  PrintSummaryTable({high, low}, two);
  lines = Lines(two.str());
  ASSERT_EQ(lines.size(), 3U) << two.str();
  EXPECT_NE(lines[1].find(" 1.750+-"), std::string::npos) << lines[1];
  EXPECT_EQ(lines[1].back(), '-');  // the mark is on rel_auc, not at the end of the line
  EXPECT_NE(lines[1].find("*"), std::string::npos) << lines[1];
  EXPECT_NE(lines[2].find("(lowest 0.010,"), std::string::npos) << lines[2];

  // A reference of AUC 0 gives no ratio (RelativeAuc: NaN): the empty cell is marked too, "-*".
  RunResult nothing = Referenced("sim", "decentralized", 0, 0.3, 0.0);
  nothing.relative_auc = std::numeric_limits<double>::quiet_NaN();
  std::ostringstream empty;
  PrintSummaryTable({nothing}, empty);
  lines = Lines(empty.str());
  ASSERT_EQ(lines.size(), 3U) << empty.str();
  ExpectRelAucCell(lines, 1, "-*");
  EXPECT_NE(lines[2].find("(lowest 0.000,"), std::string::npos) << lines[2];
}

// References at or above the threshold (0.1 exactly, 0.3): no mark, no footnote. 0.08 / 0.1 =
// 0.800.
TEST(SummaryTable, ARelativeAucOverAReferenceAtTheThresholdIsNotMarked) {
  std::ostringstream out;
  PrintSummaryTable({Referenced("sim", "decentralized", 0, 0.08, 0.1), Referenced("sim", "broadcast", 0, 0.3, 0.3)},
                    out);
  const std::vector<std::string> lines = Lines(out.str());
  ASSERT_EQ(lines.size(), 3U) << out.str();
  ExpectRelAucCell(lines, 1, "0.800");
  ExpectRelAucCell(lines, 2, "1.000");
  EXPECT_EQ(out.str().find('*'), std::string::npos) << out.str();
}

}  // namespace
}  // namespace dvpr
