// The bag-of-words strategies in the simulation protocol, from a config (LoadSharedInputs,
// RunSweepInMemory): they run (no longer refused), their relative AUC is against the simulated
// centralized BoW server, and the network counts their partial queries and replies by role with
// the sizes LCM's encoding gives them.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "experiments/config/config.h"
#include "experiments/domain/data/split.h"
#include "experiments/protocols/inputs.h"
#include "experiments/sweep/run_sweep.h"
#include "tests/kitti_every_tenth.h"
#include "tests/test_support.h"

namespace dvpr {
namespace {

namespace fs = std::filesystem;

constexpr std::size_t Role(MessageRole r) { return static_cast<std::size_t>(r); }

// Frame i's words: i mod 50, 50 + 7i mod 50, 100 + i mod 13 (weights 2, 1, 1: the loader
// L1-normalises them), so each frame has 3 words and a frame 50 or 650 frames on shares some.
std::vector<int> WordsOf(int i) { return {i % 50, 50 + (7 * i) % 50, 100 + i % 13}; }

class SimBowSweepTest : public ::testing::Test {
 protected:
  static constexpr int kDim = 16, kRobots = 3;
  void SetUp() override {
    dir_ = dvpr::testing_support::FreshTestDir("sim_bow_sweep");
    const Dataset data = testing_support::KittiEveryTenth(kDim, dir_ / "poses.txt");
    frames_ = static_cast<int>(data.size());
    std::ofstream bow(dir_ / "bow.txt");
    for (int i = 0; i < frames_; ++i) {
      const std::vector<int> w = WordsOf(i);
      bow << w[0] << ":2 " << w[1] << ":1 " << w[2] << ":1\n";
    }
  }
  std::vector<RunOutput> Run(const std::string& strategies) const {
    const ExperimentConfig config = ParseConfig(
        "name: sim_bow\nseed: 5\n"
        "dataset: {source: synthetic, poses: poses.txt, bow: bow.txt, dim: 16}\n"
        "training: {synthetic: {samples: 300}}\n"
        "robots: [3]\nruns: 1\nprotocols: [sim]\nstrategies: " + strategies + "\n"
        "network: {model: ideal}\nverification: {max_distance: 0, bow_max_distance: 0}\n"
        "evaluation: {gt_radius_m: 5, suppression_frames: 25}\noutputs: {figures: false}\n",
        dir_, {}, "sim_bow.yaml");
    SharedInputs inputs = LoadSharedInputs(config, "sim_bow.yaml");
    inputs.out_dir = dir_ / "out";
    return RunSweepInMemory(inputs, {.threads = 1, .progress = false});
  }
  fs::path dir_;
  int frames_ = 0;
};

// Ideal network: every partial query arrives and is answered by one 39-byte bow_match_t.
// Hand-counted bytes, from the words above (owner of word w: w mod 3; robot r takes frames
// [floor(rN/3), floor((r+1)N/3))): per frame, one bow_query_t of 26 + 8 x (its words owned by
// o) to each other robot o owning some; broadcast the 3 words (50 bytes) to both others;
// centralized the 3 words to robot 0 from the frames of robots 1 and 2.
TEST_F(SimBowSweepTest, RunsWithHandCountedQueryAndReplyBytes) {
  const std::vector<RunOutput> out = Run("[bow_decentralized, bow_broadcast, bow_centralized, decentralized]");
  ASSERT_EQ(out.size(), 1u);
  ASSERT_EQ(out[0].runs.size(), 4u);
  const SequenceSplit split = SplitSequence(frames_, kRobots);
  std::map<std::string, std::pair<std::int64_t, std::int64_t>> expected;  // strategy -> (queries, query bytes)
  for (int i = 0; i < frames_; ++i) {
    const int taker = split.owner[static_cast<std::size_t>(i)].value;
    std::map<int, int> words_at;
    for (const int w : WordsOf(i)) ++words_at[w % kRobots];
    for (const auto& [robot, count] : words_at) {
      if (robot == taker) continue;
      expected["bow_decentralized"].first += 1;
      expected["bow_decentralized"].second += 26 + 8 * count;
    }
    expected["bow_broadcast"].first += kRobots - 1;
    expected["bow_broadcast"].second += (kRobots - 1) * 50;
    if (taker != 0) {
      expected["bow_centralized"].first += 1;
      expected["bow_centralized"].second += 50;
    }
  }
  const RunResult* central = nullptr;
  for (const RunResult& row : out[0].runs) {
    if (row.key.strategy == "bow_centralized") central = &row;
  }
  ASSERT_NE(central, nullptr);
  for (const RunResult& row : out[0].runs) {
    SCOPED_TRACE(row.key.strategy);
    EXPECT_EQ(row.key.protocol, "sim");
    EXPECT_EQ(row.queries, frames_);
    ASSERT_TRUE(row.roles);
    const auto& copies = row.roles->copies;
    if (row.key.strategy == "decentralized") {
      EXPECT_NE(row.auc_reference, central->auc_reference);  // the descriptors' broadcast
      continue;
    }
    EXPECT_EQ(row.auc_reference, central->auc);  // the BoW server's AUC
    const auto [messages, bytes] = expected.at(row.key.strategy);
    ASSERT_GT(messages, frames_ / 2);
    EXPECT_EQ(copies[Role(MessageRole::kQuery)].payload, bytes);
    EXPECT_EQ(copies[Role(MessageRole::kReply)].payload, 39 * messages);
    EXPECT_EQ(copies[Role(MessageRole::kQuery)].delivered_payload, bytes);
    EXPECT_EQ(row.messages, 2 * messages);  // no verification (bow_max_distance 0): queries and replies
    EXPECT_EQ(row.dropped_messages, 0);
  }
}

}  // namespace
}  // namespace dvpr
