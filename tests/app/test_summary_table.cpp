// The summary table `dvpr run` prints (PrintSummaryTable): its columns stay aligned whatever the
// numbers (issue 48: "6.71+-21.38" with runs=2 pushed a row two characters past its header).
#include <gtest/gtest.h>

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

}  // namespace
}  // namespace dvpr
