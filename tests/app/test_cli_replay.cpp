// `dvpr replay` as a user runs it: a page from a real run, and its errors (one line, exit 1 for an
// input, 2 for usage, no page written).
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "tests/app/cli_test_support.h"
#include "tests/test_support.h"

namespace dvpr::testing_support {
namespace {

class ReplayCliTest : public CliTest {
 protected:
  // A short run that records its messages: 3 robots, 60 frames.
  Result RecordRun() {
    return RunConfig("name: tiny\nseed: 2\ndataset: {dim: 16, frames: 60}\ntraining: {synthetic: {samples: 300}}\n"
                     "robots: [3]\nruns: 1\nprotocols: [sim]\nevaluation: {suppression_frames: 10}\n"
                     "outputs: {figures: false, messages: true}\n");
  }
};

TEST_F(ReplayCliTest, WritesOnePageAndSaysWhere) {
  ASSERT_EQ(RecordRun().status, 0);
  const Result r = Dvpr("replay '" + Out().string() + "'");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  const path page = Out() / "replay_n3_run0_net0.html";
  EXPECT_NE(Stdout().find("replay of tiny: 3 robots, run 0, network 0 (point-to-point, 10 Mbit/s, 2 ms), "
                          "decentralized vs broadcast, "), std::string::npos) << Stdout();
  EXPECT_NE(Stdout().find(page.string()), std::string::npos) << Stdout();
  const std::string html = Slurp(page);
  EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_NE(html.find("\"strategies\":[{\"name\":\"decentralized\""), std::string::npos);
  const path other = dir_ / "elsewhere.html";
  EXPECT_EQ(Dvpr("replay '" + Out().string() + "' --strategy broadcast --out '" + other.string() + "'").status, 0);
  EXPECT_NE(Slurp(other).find("\"strategies\":[{\"name\":\"broadcast\""), std::string::npos);
}

TEST_F(ReplayCliTest, InputErrorsAreOneLineAndWriteNothing) {
  ExpectExactly(Dvpr("replay '" + Out().string() + "'"), 1, "dvpr: error: " + Out().string() + ": no such result folder");
  ASSERT_EQ(RunConfig("name: tiny\ndataset: {dim: 16, frames: 60}\ntraining: {synthetic: {samples: 300}}\n"
                      "robots: [3]\nruns: 1\nprotocols: [sim]\noutputs: {figures: false}\n").status, 0);
  const auto before = SnapshotFolder(Out());
  Result r = Dvpr("replay '" + Out().string() + "'");
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err, "dvpr: error: " + Out().string() +
                   ": no messages.csv (record it: dvpr run CONFIG --set outputs.messages=true)\n");
  ASSERT_EQ(RecordRun().status, 0);
  const auto recorded = SnapshotFolder(Out());
  r = Dvpr("replay '" + Out().string() + "' --run 4");
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err, "dvpr: error: " + (Out() / "messages.csv").string() +
                   ": no messages of run=4 (it has robots 3; runs 0; network variants 0)\n");
  EXPECT_EQ(SnapshotFolder(Out()), recorded);  // no page, no temporary left behind
  EXPECT_NE(before, recorded);
}

// A result folder whose descriptor file moved since the run: the replay reads only the folder and
// the poses, so it replays (it used to refuse the folder: "dataset.descriptors: file not found").
TEST_F(ReplayCliTest, AFolderWhoseDescriptorFileMovedStillReplays) {
  {
    std::ofstream d(dir_ / "d.csv");
    for (int f = 0; f < 60; ++f) {
      for (int k = 0; k < 16; ++k) d << (k ? "," : "") << ((f * 31 + k * 7) % 17) / 17.0;
      d << "\n";
    }
    std::ofstream poses(dir_ / "p.txt");
    for (int f = 0; f < 60; ++f) poses << "1 0 0 " << f << " 0 1 0 0 0 0 1 " << (f % 7) << "\n";
  }
  ASSERT_EQ(RunConfig("name: tiny\nseed: 2\ndataset: {source: files, poses: p.txt, descriptors: d.csv, dim: 16}\n"
                      "training: {synthetic: {samples: 300}}\nrobots: [3]\nruns: 1\nprotocols: [sim]\n"
                      "evaluation: {suppression_frames: 10}\noutputs: {figures: false, messages: true}\n")
                .status,
            0);
  std::filesystem::rename(dir_ / "d.csv", dir_ / "moved.csv");
  const Result r = Dvpr("replay '" + Out().string() + "'");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_TRUE(std::filesystem::exists(Out() / "replay_n3_run0_net0.html"));
}

TEST_F(ReplayCliTest, UsageErrorsExitTwo) {
  ExpectExactly(Dvpr("replay"), 2, "dvpr replay: dvpr replay needs a RESULT_DIR (see dvpr --help)");
  ExpectExactly(Dvpr("replay a --run x"), 2, "dvpr replay: --run: expected an integer, got 'x' (see dvpr --help)");
  ExpectExactly(Dvpr("replay a --out ''"), 2, "dvpr replay: --out: expected a value, got '' (see dvpr --help)");
  EXPECT_EQ(Dvpr("--help").status, 0);
  EXPECT_NE(Stdout().find("dvpr replay RESULT_DIR"), std::string::npos);
}

}  // namespace
}  // namespace dvpr::testing_support
