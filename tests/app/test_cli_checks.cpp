// Inputs that only fail once the data is loaded - centroid files, the pose file against
// dataset.frames, link overrides against the teams, strategies against the training set - are
// found before `dvpr run` writes anything: exit 1, the one line below (worked out from the file
// names and the shapes written here), and no result folder (issue 12).
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "experiments/domain/data/npy.h"
#include "tests/app/cli_test_support.h"

namespace dvpr {
namespace {

using testing_support::CliTest;
using testing_support::Result;

// A small sweep on a 40-pose trajectory with d = 32 synthetic descriptors.
class CliChecksTest : public CliTest {
 protected:
  void SetUp() override {
    CliTest::SetUp();
    std::ofstream poses(Poses());
    for (int i = 0; i < 40; ++i) poses << "1 0 0 " << i << " 0 1 0 0 0 0 1 0\n";
    dataset_ = "{source: synthetic, poses: '" + Poses().string() + "', dim: 32}";
  }
  path Poses() const { return dir_ / "poses.txt"; }
  // The config with `rest` appended; the dataset and training sections are members a test may change.
  std::string Yaml(const std::string& rest) const {
    return "dataset: " + dataset_ + "\ntraining: " + training_ + "\nprotocols: " + protocols_ +
           "\nrobots: [2, 3]\nruns: 2\noutputs: {figures: false}\n" + rest;
  }
  std::string protocols_ = "[paper]";
  std::string dataset_;
  std::string training_ = "{synthetic: {samples: 200, environments: 2}}";
  // Centroid files c_n{robots}_r{run}.npy of `cols` values, robots x clusters rows, all 0.5.
  void Centroids(Eigen::Index cols, int clusters = 1) const {
    for (int n : {2, 3}) {
      for (int run : {0, 1}) WriteNpy(File(n, run), CentroidMatrix::Constant(n * clusters, cols, 0.5f));
    }
  }
  path File(int robots, int run) const {
    return dir_ / ("c_n" + std::to_string(robots) + "_r" + std::to_string(run) + ".npy");
  }
  std::string WithCentroids(const std::string& rest = "") {
    training_ = "{centroids: '" + (dir_ / "c_n{robots}_r{run}.npy").string() + "'}";
    return Yaml(rest);
  }
  std::string Error(const std::string& key_and_problem) const {
    return "dvpr: error: " + Config().string() + ": " + key_and_problem;
  }
};

TEST_F(CliChecksTest, CentroidFilesOfTheRightShapeRun) {
  Centroids(32);
  const Result r = RunConfig(WithCentroids());
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(Out() / "runs.csv"));
}

// The case of issue 12: 16 columns for 32-dimensional descriptors.
TEST_F(CliChecksTest, ACentroidFileOfTheWrongWidthNamesTheFile) {
  Centroids(16);
  ExpectExactly(RunConfig(WithCentroids()), 1,
                Error("training.centroids: " + File(2, 0).string() +
                      ": 16 values per centroid, expected 32 (the descriptors' dataset.dim)"));
}

// Every run's file is read before the first run: the bad one here is the sweep's last.
TEST_F(CliChecksTest, ANonFiniteCentroidInTheLastRunNamesItsFile) {
  Centroids(32);
  CentroidMatrix c = CentroidMatrix::Constant(3, 32, 0.5f);
  c(1, 7) = std::numeric_limits<float>::quiet_NaN();
  WriteNpy(File(3, 1), c);
  ExpectExactly(RunConfig(WithCentroids()), 1,
                Error("training.centroids: " + File(3, 1).string() + ": centroid 1 (0-based row) holds NaN or Inf"));
}

TEST_F(CliChecksTest, ACentroidCountThatFitsNoTeamNamesTheFile) {
  Centroids(32);
  WriteNpy(File(3, 0), CentroidMatrix::Constant(2, 32, 0.5f));
  ExpectExactly(RunConfig(WithCentroids()), 1,
                Error("training.centroids: " + File(3, 0).string() + ": 2 centroids, expected 3 (3 robots x 1 per robot)"));
}

// lpt_c2 reads the same files with its own C = 2: 4 centroids for 2 robots.
TEST_F(CliChecksTest, AStrategyWithItsOwnClusterCountChecksTheFilesForIt) {
  Centroids(32);
  ExpectExactly(RunConfig(WithCentroids("strategies: [decentralized, lpt_c2]\n")), 1,
                Error("training.centroids: " + File(2, 0).string() +
                      ": 2 centroids, expected 4 (2 robots x 2 per robot) (strategy 'lpt_c2')"));
}

TEST_F(CliChecksTest, AStrategyThatNeedsTheTrainingDescriptorsIsRefusedWithCentroidFiles) {
  Centroids(32);
  ExpectExactly(RunConfig(WithCentroids("strategies: [decentralized, balanced_c2]\n")), 1,
                Error("strategies[1]: 'balanced_c2' needs the training descriptors, but training.centroids "
                      "replaces them (drop the strategy or training.centroids)"));
}

// 200 training descriptors cannot make k = 3 robots x 100 clusters.
TEST_F(CliChecksTest, AStrategyWithMoreClustersThanTrainingDescriptorsIsRefused) {
  ExpectExactly(RunConfig(Yaml("strategies: [decentralized, lpt_c100]\n")), 1,
                Error("strategies[1]: 'lpt_c100' clusters the training descriptors into k = 300 (3 robots x 100), "
                      "but there are only 200"));
}

// recluster_c11000 for 3 robots sends tables of 33000 centroids in the simulation, more than
// centroid_table_t's int16 k holds: refused before the training check, which it would also fail.
// The paper protocol evaluates the same plan without messages and checks only the training side.
TEST_F(CliChecksTest, AReclusteringTableLongerThanAMessageCarriesIsRefusedForTheSimulation) {
  protocols_ = "[paper, sim]";
  ExpectExactly(RunConfig(Yaml("strategies: [decentralized, recluster_c11000_p50]\n")), 1,
                Error("strategies[1]: 'recluster_c11000_p50' sends tables of 33000 centroids (3 robots x 11000), "
                      "but a centroid_table_t carries at most 32767 (its k is an int16 on the wire)"));
  protocols_ = "[paper]";
  ExpectExactly(RunConfig(Yaml("strategies: [decentralized, recluster_c11000_p50]\n")), 1,
                Error("strategies[1]: 'recluster_c11000_p50' clusters the training descriptors into k = 33000 "
                      "(3 robots x 11000), but there are only 200"));
}

// A npy header holding a newline and a control byte: still one line.
TEST_F(CliChecksTest, ABrokenCentroidFileHeaderIsOneLine) {
  Centroids(32);
  std::string header = "{'descr': '<f4', 'fortran_order': False, 'shape': (2, 32), 'x\n\x01': 1}";
  header += std::string(64 - (10 + header.size() + 1) % 64, ' ') + "\n";
  std::ofstream bad(File(2, 0), std::ios::binary);
  bad << std::string("\x93NUMPY\x01\x00", 8) << static_cast<char>(header.size() % 256)
      << static_cast<char>(header.size() / 256) << header << std::string(256, '\0');
  bad.close();
  const Result r = RunConfig(WithCentroids());
  ExpectConfigError(r, Config().string() + ": training.centroids: npy file " + File(2, 0).string() +
                           ": bad header (unknown key 'x\\n\\x01'): '{'descr'");
}

// The synthetic source used to run the 40 poses there are while config.yaml said 50.
TEST_F(CliChecksTest, FramesBeyondThePoseFileAreRefusedForTheSyntheticSource) {
  ExpectExactly(RunConfig(Yaml(""), "--set dataset.frames=50"), 1,
                Error("dataset.frames: 50 frames requested, but the pose file " + Poses().string() + " has only 40"));
}

TEST_F(CliChecksTest, FramesBeyondThePoseFileAreRefusedForTheFilesSource) {
  std::ofstream d(dir_ / "d.csv");
  for (int i = 0; i < 40; ++i) d << i + 1 << ",1,2\n";
  d.close();
  dataset_ = "{source: files, poses: '" + Poses().string() + "', descriptors: '" + (dir_ / "d.csv").string() +
             "', dim: 3, frames: 41}";
  ExpectExactly(RunConfig(Yaml("")), 1, Error("dataset.frames: 41 frames requested, but the pose file " + Poses().string() + " has only 40"));
}

// With descriptor files, an error in the pose file used to be labelled dataset.descriptors.
TEST_F(CliChecksTest, APoseFileErrorIsLabelledWithThePoseKey) {
  std::ofstream(dir_ / "d.csv") << "1,2\n3,4\n";
  std::ofstream(dir_ / "p.txt") << "1 0 0 0 0 1 0 0 0 0 1 0\n1 0 0\n";
  dataset_ = "{source: files, poses: '" + (dir_ / "p.txt").string() + "', descriptors: '" +
             (dir_ / "d.csv").string() + "', dim: 2}";
  ExpectExactly(RunConfig(Yaml("")), 1,
                Error("dataset.poses: " + (dir_ / "p.txt").string() + ": line 2: expected 12 numbers (a 3x4 pose), got 3"));
}

// Robot 2 is in the team of 3 but not in the team of 2, which used to fail mid-sweep.
TEST_F(CliChecksTest, ALinkOverrideOutsideATeamIsRefusedBeforeTheRuns) {
  protocols_ = "[sim]";
  ExpectExactly(RunConfig(Yaml("network: {links: [{src: 0, dst: 2, latency: 1ms}]}\n")), 1,
                Error("network.links[0]: 0->2 is not a link between two of the 2 robots (robots: 2, 3; every team "
                      "of the sweep runs the same network section)"));
}

// Users' own BoW vectors (docs/bow.md): the same 40 frames as text lines and as binary triples
// give the same run, byte for byte; a file with a frame too few names the key and both counts.
class CliBowFileTest : public CliChecksTest {
 protected:
  // Frame i has words i mod 7 and 10 + i mod 5 with weights 1 and 2 (so frames 0 and 35 share
  // both words, frames 0 and 5 one: revisits for the static protocol's ranking).
  void WriteText(const path& p, int frames) const {
    std::ofstream out(p);
    for (int i = 0; i < frames; ++i) out << i % 7 << ":1 " << 10 + i % 5 << ":2\n";
  }
  void WriteTriples(const path& p, int frames) const {
    std::ofstream out(p, std::ios::binary);
    const auto put = [&](std::uint32_t v) {
      for (int b = 0; b < 4; ++b) out.put(static_cast<char>((v >> (8 * b)) & 0xffu));
    };
    for (int i = frames - 1; i >= 0; --i) {  // last frame first: the order must not matter
      put(static_cast<std::uint32_t>(i)), put(static_cast<std::uint32_t>(10 + i % 5)), put(0x40000000u);  // 2.0f
      put(static_cast<std::uint32_t>(i)), put(static_cast<std::uint32_t>(i % 7)), put(0x3f800000u);       // 1.0f
    }
  }
  std::string RunsCsv(const path& bow) {
    const Result r = RunConfig(Yaml("strategies: [bow_decentralized, bow_centralized]\n"),
                               "--set dataset.bow='" + bow.string() + "'");
    EXPECT_EQ(r.status, 0) << r.err;
    std::ifstream in(Out() / "runs.csv");
    std::string csv((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::filesystem::remove_all(Out());
    return csv;
  }
};

TEST_F(CliBowFileTest, TextLinesAndBinaryTriplesGiveTheSameRun) {
  WriteText(dir_ / "bow.txt", 40);
  WriteTriples(dir_ / "bow.bin", 40);
  const std::string text = RunsCsv(dir_ / "bow.txt");
  EXPECT_NE(text.find("bow_decentralized"), std::string::npos);
  EXPECT_EQ(RunsCsv(dir_ / "bow.bin"), text);
}

TEST_F(CliBowFileTest, ABinaryFileWithAFrameTooFewNamesTheKeyAndTheCounts) {
  WriteTriples(dir_ / "bow.bin", 39);
  const path bow = dir_ / "bow.bin";
  ExpectExactly(RunConfig(Yaml("strategies: [bow_decentralized]\n"), "--set dataset.bow='" + bow.string() + "'"), 1,
                Error("dataset.bow: " + bow.string() + " has 39 frames, the dataset 40"));
}

// synthetic_bow at its documented maxima of landmarks, 60000 frames: (2 x 1000 m)^2 x 10 landmarks
// examined a frame, 1.7 s each (100 features a frame: at 100000 its 112 GiB of words and vectors
// would be refused first, by memory), 102000 s (28.3 h) before the first run, on any number of cores. Refused
// before the inputs are made (dataset.frames bounds them): one line, nothing written, at once.
TEST_F(CliChecksTest, ASweepOfMoreThanADayIsRefusedBeforeTheInputsAreMade) {
  dataset_ = "{source: synthetic, poses: '" + Poses().string() + "', dim: 32, frames: 60000, synthetic_bow: "
             "{features: 100, vocabulary: 10000000, landmark_density: 10, range_m: 1000, field_of_view_deg: 360}}";
  const Result r = RunConfig(Yaml("strategies: [bow_decentralized]\n"));
  ExpectConfigError(r, Config().string() + ": robots, runs, strategies, network, dataset: the sweep would take about "
                                           "28.3 h on ");
  EXPECT_NE(r.err.find("(4 runs of up to 5.76 s each, and 1.02e+05 s to make dataset.synthetic_bow's vectors), "
                       "more than 24 h; narrow it, or pass --allow-large to run it anyway\n"),
            std::string::npos)
      << r.err;
}

}  // namespace
}  // namespace dvpr
