// Figure 9's data files (figures_bow.cpp) go through the one writer (safe_output.h): a symbolic
// link planted at any of their names is replaced, never followed (they were written with
// std::ofstream, which wrote through such a link into its target), and what they hold is worked
// out by hand from a small runs, bow.csv and bow_sizes.csv.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "experiments/figures/figures.h"
#include "experiments/results/result_writers.h"
#include "tests/test_support.h"

namespace dvpr {
namespace {

namespace fs = std::filesystem;
using testing_support::Names;
using testing_support::Slurp;

const std::vector<std::string> kBowFiles = {"bow_auc.dat", "bow_auc_ci.dat", "bow_bytes.dat", "bow_sizes.dat", "bow_sizes.titles",
                                            "bow_vote.dat"};

RunResult Paper(const std::string& strategy, int robots, int run, double rel) {
  RunResult r;
  r.key = RunKey{.protocol = "paper", .strategy = strategy, .robots = robots, .run = run, .network = {}};
  r.relative_auc = rel;
  return r;
}

class BowFigureData : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = dvpr::testing_support::FreshTestDir("figures_bow");
    fs::create_directories(data());
    fs::create_directories(dir_ / "elsewhere");
    std::ofstream(victim()) << "precious";
    // Only the columns the figure reads (it reads by header name).
    std::ofstream(dir_ / "bow.csv") << "protocol,strategy,robots,query_bytes_per_query,vote_not_centralized_fraction\n"
                                       "paper,bow_decentralized,2,300,0.25\n"
                                       "sim,bow_decentralized,2,999,1\n";
    // 66 bytes: (66 - 26) / 8 = 5 words, bin 1; 42 bytes: 2 words, bin 0. Run 1 is not shown.
    std::ofstream(dir_ / "bow_sizes.csv") << "strategy,protocol,run,robots,payload_bytes,messages\n"
                                             "bow_decentralized,paper,0,2,66,3\n"
                                             "bow_decentralized,paper,0,2,42,1\n"
                                             "bow_decentralized,paper,1,2,42,50\n";
  }
  fs::path data() const { return dir_ / "figures" / "data"; }
  fs::path victim() const { return dir_ / "elsewhere" / "victim.txt"; }
  bool Write() {
    return WriteBowComparisonData(dir_, data(), {Paper("decentralized", 2, 0, 0.5), Paper("bow_decentralized", 2, 0, 0.5),
                                                 Paper("bow_decentralized", 2, 1, 0.75)});
  }
  fs::path dir_;
};

constexpr const char* kDesigns = " decentralized broadcast bow_decentralized bow_decentralized_df bow_broadcast\n";

TEST_F(BowFigureData, TheFilesHoldTheMeansWorkedByHand) {
  ASSERT_TRUE(Write());
  EXPECT_EQ(Names(data()), kBowFiles);  // no temporary left
  EXPECT_EQ(Slurp(data() / "bow_auc.dat"),
            std::string("# n, then mean relative AUC (paper protocol) of:") + kDesigns + "2 0.5 NaN 0.625 NaN NaN\n");
  // The spread beside each mean: one run of decentralized has none; bow_decentralized's 0.5 and
  // 0.75 have sample std 0.25 / sqrt(2), so the half-width is t(0.975, 1) x 0.25 / 2 with
  // t(0.975, 1) = tan(0.475 pi) (the Cauchy quantile): 1.5882755920...
  const std::string ci = Slurp(data() / "bow_auc_ci.dat");
  const std::string header =
      std::string("# n, then relative AUC (paper protocol) (mean, 95 % CI half-width) of:") + kDesigns;
  ASSERT_EQ(ci.substr(0, header.size()), header);
  std::istringstream line(ci.substr(header.size()));
  std::vector<std::string> f;
  for (std::string x; line >> x;) f.push_back(x);
  ASSERT_EQ(f.size(), 11u) << ci;
  EXPECT_EQ(f[0], "2");
  EXPECT_EQ(f[1], "0.5");
  EXPECT_EQ(f[2], "NaN");
  EXPECT_EQ(f[3] + f[4], "NaNNaN");
  EXPECT_EQ(f[5], "0.625");
  EXPECT_NEAR(std::stod(f[6]), std::tan(0.475 * std::numbers::pi) * 0.125, 1e-12);
  EXPECT_EQ(f[7] + f[8] + f[9] + f[10], "NaNNaNNaNNaN");
  EXPECT_EQ(Slurp(data() / "bow_bytes.dat"),
            std::string("# n, then mean query bytes per query of:") + kDesigns + "2 NaN NaN 300 NaN NaN\n");
  EXPECT_EQ(Slurp(data() / "bow_vote.dat"), std::string("# n, then share of votes not the centralized BoW best of:") +
                                                kDesigns + "2 NaN NaN 0.25 NaN NaN\n");
  // Bin centres 26 + 8 * (5 * bin + 2): 42 and 82 bytes; shares 1/4 and 3/4 of run 0's 4 messages.
  EXPECT_EQ(Slurp(data() / "bow_sizes.dat"), "# n = 2: bin centre (bytes), share of messages\n42 0.25\n82 0.75\n\n\n");
  EXPECT_EQ(Slurp(data() / "bow_sizes.titles"), "2\n");
}

// A link at every name the figure writes (where std::ofstream wrote through it): each is
// replaced by the file, the link's target is untouched.
TEST_F(BowFigureData, LinksPlantedAtItsNamesAreReplacedNotFollowed) {
  for (const std::string& name : kBowFiles) fs::create_symlink(victim(), data() / name);
  ASSERT_TRUE(Write());
  EXPECT_EQ(Slurp(victim()), "precious");
  EXPECT_EQ(Names(data()), kBowFiles);
  for (const std::string& name : kBowFiles) {
    EXPECT_FALSE(fs::is_symlink(data() / name)) << name;
    EXPECT_TRUE(fs::is_regular_file(data() / name)) << name;
  }
  EXPECT_EQ(Slurp(data() / "bow_sizes.titles"), "2\n");
}

// The data folder itself a link: refused naming it, nothing written through it.
TEST_F(BowFigureData, ADataFolderThatIsALinkIsRefused) {
  fs::remove_all(data());
  fs::create_directory_symlink(dir_ / "elsewhere", data());
  try {
    Write();
    FAIL() << "a data folder that is a link was written through";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find((data()).string()), std::string::npos) << e.what();
  }
  EXPECT_EQ(Names(dir_ / "elsewhere"), std::vector<std::string>{"victim.txt"});
}

// The bytes panel (log scale) marks the seed paper's sizes as horizontal lines: 16 kB for BoW's
// distributed query (about 2000 words of 8 bytes) and 512 bytes for NetVLAD's query to one robot.
TEST_F(BowFigureData, TheBytesPanelMarksTheSeedPapersQuerySizes) {
  ASSERT_TRUE(Write());
  const std::string script = BowComparisonScript(data(), dir_ / "figures" / "bow_comparison.png");
  const auto panel = script.find("set title 'Query bytes per query");
  ASSERT_NE(panel, std::string::npos);
  const auto plot = script.find("plot ", panel);
  const std::string line = script.substr(plot, script.find('\n', plot) - plot);
  EXPECT_LT(script.find("set logscale y", panel), plot);
  EXPECT_NE(line.find(", 16000 with lines"), std::string::npos) << line;
  EXPECT_NE(line.find("title 'seed paper: BoW query, 16 kB'"), std::string::npos) << line;
  EXPECT_NE(line.find(", 512 with lines"), std::string::npos) << line;
  EXPECT_NE(line.find("title 'seed paper: NetVLAD query, 512 B'"), std::string::npos) << line;
  // Both methods' own lines are still there: the global descriptor's and the distributed index's.
  EXPECT_NE(line.find("'bow_bytes.dat' using 1:2 "), std::string::npos) << line;
  EXPECT_NE(line.find("'bow_bytes.dat' using 1:4 "), std::string::npos) << line;
}

}  // namespace
}  // namespace dvpr
