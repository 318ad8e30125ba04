// A team of its own trajectories through the dvpr binary (issue 35, items 1 and 2): robot 0
// drives a 40 m square, robot 1 the same square the other way round 30 s later, each from its
// own Kimera-Multi CSV file (dataset.trajectories). The inter- and intra-robot revisits and the
// first inter-robot closure are counted by hand from the poses and times alone; the scenarios on
// KITTI 00 run in both protocols and keep their plan; what a planned team cannot run with is one
// named error.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "experiments/config/config.h"
#include "experiments/protocols/inputs.h"
#include "tests/app/cli_test_support.h"

namespace dvpr::testing_support {
namespace {

namespace fs = std::filesystem;

// The perimeter of a 40 m square on the ground plane (x, z), a point every 10 m: p(0) = (0, 0),
// p(4) = (40, 0), p(8) = (40, 40), p(12) = (0, 40), p(16) = p(0). The camera faces +z throughout
// (identity quaternion), so both robots see a place from the same side.
std::string SquareCsv(bool reversed) {
  std::string csv = "timestamp_kf(ns),x,y,z,qw,qx,qy,qz\n";
  for (int m = 0; m <= 16; ++m) {
    const int k = reversed ? 16 - m : m;
    double x = 0, z = 0;
    if (k <= 4) x = 10.0 * k;
    else if (k <= 8) x = 40, z = 10.0 * (k - 4);
    else if (k <= 12) x = 40 - 10.0 * (k - 8), z = 40;
    else z = 40 - 10.0 * (k - 12);
    csv += std::to_string(static_cast<long long>(m) * 1000000000LL) + "," + std::to_string(x) + ",0," +
           std::to_string(z) + ",1,0,0,0\n";
  }
  return csv;
}

class TeamPlanCliTest : public CliTest {
 protected:
  std::string SquaresYaml() {
    std::ofstream(dir_ / "robot0.csv") << SquareCsv(false);
    std::ofstream(dir_ / "robot1.csv") << SquareCsv(true);
    return "name: squares\nseed: 1\n"
           "dataset:\n  source: synthetic\n  dim: 16\n  fps: 1\n  synthetic: {noise: 0.05}\n  trajectories:\n"
           "    - {poses: '" + (dir_ / "robot0.csv").string() + "', format: csv, start: 0s}\n"
           "    - {poses: '" + (dir_ / "robot1.csv").string() + "', format: csv, start: 30s}\n"
           "training: {synthetic: {samples: 500}}\nrobots: [2]\nruns: 1\nprotocols: [sim]\n"
           "strategies: [decentralized, broadcast]\nevaluation: {gt_radius_m: 5, suppression_frames: 2}\n"
           "verification: {max_distance: 100}\nnetwork: {model: point_to_point}\n"
           "outputs: {figures: false, queries: true}\n";
  }
  std::string KittiYaml(const std::string& scenario, int robots) const {
    return "name: scenario\nseed: 1\ndataset: {source: synthetic, poses: '" + std::string(DVPR_SOURCE_DIR) +
           "/data/kitti/00_poses.txt', dim: 16, fps: 10, frames: 200, scenario: " + scenario +
           "}\ntraining: {synthetic: {samples: 500}}\nrobots: [" + std::to_string(robots) +
           "]\nruns: 1\nprotocols: [sim]\nstrategies: [decentralized, broadcast]\n"
           "evaluation: {gt_radius_m: 5, suppression_frames: 20}\nnetwork: {model: point_to_point}\n"
           "outputs: {figures: false, queries: true}\n";
  }
};

TEST_F(TeamPlanCliTest, SquareAndItsReverseThirtySecondsLaterCountedByHand) {
  const Result r = RunConfig(SquaresYaml());
  ASSERT_EQ(r.status, 0) << r.err;
  // Team rows: robot 0's frames 0..16 at p(0..16), taken at 0..16 s; robot 1's 17..33 at p(16),
  // p(15), ..., p(0), taken at 30..46 s. Window 2 frames, inside each robot's own stream.
  // Robot 0's frames 0..15 lie 10 m from every earlier frame: not relevant. Frame 16 is back at
  // p(0), where its own frame 0 lies (16 frames back): intra. Every frame of robot 1 lies where
  // robot 0 passed before 30 s: inter (frame 33 also at its own frame 17, but another robot's
  // frame makes it inter). Frame 17 (robot 1's first, at p(0)) is one team row after robot 0's
  // frame 16 at the same place; another robot's stream, so not suppressed.
  std::map<std::string, std::map<std::string, int>> classes;  // strategy -> class -> queries
  std::map<std::string, int> queries;
  for (const Row& q : ReadCsv(Out() / "queries.csv")) {
    ++queries[q.at("strategy")];
    const int frame = std::stoi(q.at("frame"));
    const std::string expected = frame < 16 ? "" : frame == 16 ? "intra" : "inter";
    EXPECT_EQ(q.at("class"), expected) << q.at("strategy") << " frame " << frame;
    EXPECT_EQ(q.at("robot"), frame < 17 ? "0" : "1") << frame;
    // Taken at the robot's own times: frame 17 at 30 s, frame 33 at 46 s.
    const long long taken_s = frame < 17 ? frame : 30 + (frame - 17);
    EXPECT_EQ(std::stoll(q.at("sent_ns")), taken_s * 1000000000LL) << frame;
    ++classes[q.at("strategy")][q.at("class")];
  }
  for (const std::string s : {"decentralized", "broadcast"}) {
    EXPECT_EQ(queries[s], 34) << s;
    EXPECT_EQ(classes[s]["inter"], 17) << s;
    EXPECT_EQ(classes[s]["intra"], 1) << s;
  }
  // runs.csv: the same counts. Broadcast searches robot 1's first query (at 30 s, at p(0)) in
  // robot 0's store, which holds frames 0 and 16 at p(0) (descriptor noise 0.05: the same place,
  // seen from the same side, is the nearest); its verification closes the pair at 30 s.
  for (const Row& run : ReadCsv(Out() / "runs.csv")) {
    EXPECT_EQ(run.at("inter_queries"), "17") << run.at("strategy");
    EXPECT_EQ(run.at("intra_queries"), "1") << run.at("strategy");
    if (run.at("strategy") == "broadcast") {
      EXPECT_EQ(run.at("pairs_closed"), "1");
      EXPECT_EQ(std::stod(run.at("median_first_closure_s")), 30.0);
    }
  }
  bool broadcast_pair = false;
  for (const Row& p : ReadCsv(Out() / "closure_pairs.csv")) {
    EXPECT_EQ(p.at("robot_a"), "0");
    EXPECT_EQ(p.at("robot_b"), "1");
    if (p.at("strategy") == "broadcast") {
      broadcast_pair = true;
      EXPECT_EQ(p.at("first_closure_ns"), "30000000000");
    } else if (!p.at("first_closure_ns").empty()) {
      // No closure can come before robot 1 takes its first frame.
      EXPECT_GE(std::stoll(p.at("first_closure_ns")), 30000000000LL);
    }
  }
  EXPECT_TRUE(broadcast_pair);
  // config.yaml keeps the trajectories, and runs again to the same queries.
  const std::string written = [&] {
    std::ifstream in(Out() / "config.yaml");
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }();
  EXPECT_NE(written.find("trajectories:"), std::string::npos);
  EXPECT_NE(written.find("start: 30s"), std::string::npos) << written;
}

TEST_F(TeamPlanCliTest, StaggeredAndReverseRunOnKitti) {
  {
    std::string yaml = KittiYaml("{kind: staggered, offset: 5s}", 3);
    const Result r = RunConfig(yaml.replace(yaml.find("protocols: [sim]"), 16, "protocols: [paper, sim]"));
    ASSERT_EQ(r.status, 0) << r.err;
    // The paper protocol takes every one of the team's 600 frames as a query.
    int paper = 0;
    for (const Row& run : ReadCsv(Out() / "runs.csv")) {
      if (run.at("protocol") != "paper") continue;
      ++paper;
      EXPECT_EQ(run.at("queries"), "600") << run.at("strategy");
    }
    EXPECT_EQ(paper, 2);
    // Three robots each drive all 200 frames, robot r from 5 r s: robot 2's first frame at 10 s.
    int robot2_first = -1;
    long long sent = -1;
    for (const Row& q : ReadCsv(Out() / "queries.csv")) {
      if (q.at("strategy") != "broadcast" || q.at("robot") != "2") continue;
      if (robot2_first < 0 || std::stoi(q.at("frame")) < robot2_first) {
        robot2_first = std::stoi(q.at("frame"));
        sent = std::stoll(q.at("sent_ns"));
      }
    }
    EXPECT_EQ(robot2_first, 400);
    EXPECT_EQ(sent, 10000000000LL);
  }
  fs::remove_all(Out());
  const Result r = RunConfig(KittiYaml("reverse", 2));
  ASSERT_EQ(r.status, 0) << r.err;
  // Both drive all 200 frames from 0 s, robot 1 backwards: its frames are team rows 200..399.
  int frames = 0;
  for (const Row& q : ReadCsv(Out() / "queries.csv")) frames += q.at("strategy") == "broadcast" ? 1 : 0;
  EXPECT_EQ(frames, 400);
}

TEST_F(TeamPlanCliTest, WhatAPlannedTeamCannotRunWithIsANamedError) {
  const auto error = [&](const std::string& yaml) {
    const Result r = RunConfig(yaml);
    EXPECT_NE(r.status, 0);
    EXPECT_FALSE(fs::exists(Out() / "runs.csv"));
    return r.err;
  };
  std::string yaml;
  EXPECT_NE(error(KittiYaml("{kind: staggered}", 3)).find("dataset.scenario.offset: staggered needs a positive offset"),
            std::string::npos);
  EXPECT_NE(error(KittiYaml("{kind: random_routes, length: 5000}", 3)).find("dataset.scenario: length: 5000 frames, the sequence has 200"),
            std::string::npos);
  EXPECT_NE(error(KittiYaml("zigzag", 3)).find("dataset.scenario"), std::string::npos);
  yaml = KittiYaml("reverse", 2);
  EXPECT_NE(error(yaml.replace(yaml.find("strategies: ["), 13, "strategies: [bow_decentralized, ")).find("strategies: dataset.scenario reverse: strategy bow_decentralized is not available"),
            std::string::npos);
  yaml = SquaresYaml();
  EXPECT_NE(error(yaml.replace(yaml.find("robots: [2]"), 11, "robots: [2, 3]"))
                .find("robots: 3 robots, but dataset.trajectories gives 2 (a team of n robots drives the first n "
                      "trajectories): every count at most 2"),
            std::string::npos);
  // A launched team larger than the plan is refused before any agent starts.
  std::ofstream(Config()) << KittiYaml("{kind: staggered, offset: 5s}", 3);
  const Result launch = Dvpr("launch --config '" + Config().string() + "' --robots 4 --out '" + Out().string() + "'");
  EXPECT_NE(launch.status, 0);
  EXPECT_NE(launch.err.find("--robots: 4 robots, but the config's team plan (dataset.trajectories or "
                            "dataset.scenario) has 3"),
            std::string::npos)
      << launch.err;
  EXPECT_FALSE(fs::exists(Out()));
}


// The squares team with descriptor files of its own (issue 50, item 1): each robot's rows of the
// synthetic source's rendering, written to its own .csv file (9 significant digits: float32 reads
// back exactly), given as dataset.trajectories[i].descriptors with dataset.source files. Both
// protocols write the same numbers as the synthetic source's run, file for file.
TEST_F(TeamPlanCliTest, OwnDescriptorFilesGiveTheNumbersOfTheSyntheticSource) {
  std::string yaml = SquaresYaml();
  yaml.replace(yaml.find("protocols: [sim]"), 16, "protocols: [paper, sim]");
  const ExperimentConfig config = ParseConfig(yaml, dir_, {}, "squares.yaml");
  const SharedInputs synthetic = LoadSharedInputs(config, "squares.yaml");
  ASSERT_EQ(synthetic.deployment.size(), 34);
  for (int r = 0; r < 2; ++r) {
    std::ofstream csv(dir_ / ("robot" + std::to_string(r) + "_desc.csv"));
    csv.precision(9);
    for (int i = 17 * r; i < 17 * (r + 1); ++i) {
      for (int j = 0; j < 16; ++j) csv << (j ? "," : "") << synthetic.deployment.descriptors(i, j);
      csv << "\n";
    }
  }
  ASSERT_EQ(RunConfig(yaml).status, 0);
  const fs::path reference = dir_ / "synthetic_out";
  fs::rename(Out(), reference);
  std::string files = yaml;
  files.replace(files.find("source: synthetic"), 17, "source: files");
  for (int r = 0; r < 2; ++r) {
    const std::string csv = "robot" + std::to_string(r) + ".csv', format: csv";
    files.replace(files.find(csv), csv.size(),
                  csv + ", descriptors: '" + (dir_ / ("robot" + std::to_string(r) + "_desc.csv")).string() + "'");
  }
  const Result r = RunConfig(files);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto text = [](const fs::path& p) {
    std::ifstream in(p);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  };
  for (const std::string f : {"runs.csv", "per_robot.csv", "links.csv", "queries.csv", "closure_pairs.csv"}) {
    ASSERT_TRUE(fs::exists(reference / f)) << f;
    EXPECT_EQ(text(Out() / f), text(reference / f)) << f;
  }
  int paper = 0;
  for (const Row& run : ReadCsv(Out() / "runs.csv")) paper += run.at("protocol") == "paper" ? 1 : 0;
  EXPECT_EQ(paper, 2);
}


// A team plan swept over team sizes (issue 50, item 2): robots [2, 3] runs teams of the plan's
// first 2 and 3 robots. Each team's rows, in both protocols, are those of a config made for that
// team alone: for KITTI 00 staggered, the scenario planned for 2 robots; for three trajectories,
// a config listing only the first two (the synthetic model renders each team along its own poses).
class TeamSweepCliTest : public TeamPlanCliTest {
 protected:
  // Rows of `file` of runs of `robots` robots, in order, whole lines (the header first).
  static std::vector<std::string> LinesOf(const fs::path& file, int robots) {
    const auto fields = [](const std::string& line) {
      std::vector<std::string> out(1);
      for (const char c : line) {
        if (c == ',') {
          out.emplace_back();
        } else {
          out.back().push_back(c);
        }
      }
      return out;
    };
    std::ifstream in(file);
    std::string header, line;
    std::getline(in, header);
    const std::vector<std::string> names = fields(header);
    const auto column = static_cast<std::size_t>(std::find(names.begin(), names.end(), "robots") - names.begin());
    EXPECT_LT(column, names.size()) << file;
    std::vector<std::string> lines{header};
    while (std::getline(in, line)) {
      const std::vector<std::string> values = fields(line);
      if (column < values.size() && values[column] == std::to_string(robots)) lines.push_back(line);
    }
    return lines;
  }
  // Runs `sweep` (robots [2, 3]) and, for each n, `alone(n)`; compares the rows of each n.
  void ExpectEachTeamAsAlone(const std::string& sweep, const std::function<std::string(int)>& alone) {
    const Result r = RunConfig(sweep);
    ASSERT_EQ(r.status, 0) << r.err;
    const fs::path swept = dir_ / "swept";
    fs::rename(Out(), swept);
    for (const int n : {2, 3}) {
      const Result one = RunConfig(alone(n));
      ASSERT_EQ(one.status, 0) << one.err;
      for (const std::string f : {"runs.csv", "per_robot.csv", "queries.csv"}) {
        const std::vector<std::string> mine = LinesOf(swept / f, n);
        EXPECT_GT(mine.size(), 1u) << f << " n=" << n;
        EXPECT_EQ(mine, LinesOf(Out() / f, n)) << f << " n=" << n;
      }
      fs::remove_all(Out());
    }
  }
  static std::string Replaced(std::string s, const std::string& from, const std::string& to) {
    return s.replace(s.find(from), from.size(), to);
  }
};

TEST_F(TeamSweepCliTest, AStaggeredSweepRunsEachTeamAsItsOwnPlan) {
  const std::string yaml = Replaced(KittiYaml("{kind: staggered, offset: 5s}", 3), "protocols: [sim]", "protocols: [paper, sim]");
  ExpectEachTeamAsAlone(Replaced(yaml, "robots: [3]", "robots: [2, 3]"),
                        [&](int n) { return Replaced(yaml, "robots: [3]", "robots: [" + std::to_string(n) + "]"); });
}

TEST_F(TeamSweepCliTest, ThreeTrajectoriesRunTeamsOfTheirFirstRobots) {
  std::ofstream(dir_ / "robot2.csv") << SquareCsv(false);
  const std::string two = Replaced(SquaresYaml(), "protocols: [sim]", "protocols: [paper, sim]");
  const std::string entry = "    - {poses: '" + (dir_ / "robot2.csv").string() + "', format: csv, start: 60s}\n";
  const std::string three = Replaced(two, "training:", entry + "training:");
  ExpectEachTeamAsAlone(Replaced(three, "robots: [2]", "robots: [2, 3]"),
                        [&](int n) { return n == 2 ? two : Replaced(three, "robots: [2]", "robots: [3]"); });
  // The swept runs.csv holds both teams: 34 queries of the team of 2, 51 of the team of 3.
  std::map<std::string, std::string> queries;
  for (const Row& run : ReadCsv(dir_ / "swept" / "runs.csv")) {
    if (run.at("protocol") == "paper" && run.at("strategy") == "broadcast") queries[run.at("robots")] = run.at("queries");
  }
  EXPECT_EQ(queries, (std::map<std::string, std::string>{{"2", "34"}, {"3", "51"}}));
}


// The shipped example team (issue 50, item 5): experiments/configs/own_team.yaml with its three
// robots' TUM and descriptor files (data/own_team/, made once by scripts/make_own_team.py), swept
// over robots [2, 3] in both protocols, writes the numbers of the same team given through the
// synthetic source (the same trajectories without their files): every row, file for file.
TEST_F(TeamPlanCliTest, OwnTeamRunsAsTheSameTeamFromTheSyntheticSource) {
  const std::string config = std::string(DVPR_SOURCE_DIR) + "/experiments/configs/own_team.yaml";
  const std::string quick = " --set runs=1 --set outputs.messages=false --set outputs.figures=false";
  const auto run = [&](const std::string& out, const std::string& extra) {
    return Dvpr("run '" + config + "' --quiet --out '" + (dir_ / out).string() + "'" + quick + extra);
  };
  const Result files = run("files", "");
  ASSERT_EQ(files.status, 0) << files.err;
  std::string entries;
  for (int r = 0; r < 3; ++r) {
    entries += std::string(r ? ", " : "") + "{poses: " + DVPR_SOURCE_DIR + "/data/own_team/robot" + std::to_string(r) +
               ".txt, format: tum, start: " + std::to_string(20 * r) + "s}";
  }
  const Result synthetic = run("synthetic", " --set dataset.source=synthetic --set 'dataset.trajectories=[" + entries + "]'");
  ASSERT_EQ(synthetic.status, 0) << synthetic.err;
  const auto text = [](const fs::path& p) {
    std::ifstream in(p);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  };
  for (const std::string f : {"runs.csv", "per_robot.csv", "links.csv", "queries.csv", "closure_pairs.csv"}) {
    ASSERT_TRUE(fs::exists(dir_ / "synthetic" / f)) << f;
    EXPECT_EQ(text(dir_ / "files" / f), text(dir_ / "synthetic" / f)) << f;
  }
  // Both protocols, both teams: 1200 queries of the team of 2, 1800 of the team of 3.
  std::map<std::string, int> rows;
  for (const Row& row : ReadCsv(dir_ / "files" / "runs.csv")) {
    ++rows[row.at("protocol") + " " + row.at("robots")];
    EXPECT_EQ(row.at("queries"), row.at("robots") == "2" ? "1200" : "1800") << row.at("protocol") << row.at("strategy");
  }
  EXPECT_EQ(rows, (std::map<std::string, int>{{"paper 2", 2}, {"paper 3", 2}, {"sim 2", 2}, {"sim 3", 2}}));
}


// dvpr descriptors (scripts/make_own_team.py's step): own_team.yaml's trajectories through the
// synthetic source give, byte for byte, the descriptor files data/own_team/ ships (so they are
// what the script writes today); a config without a team plan is one error line, no folder; a
// missing --out is a usage error.
TEST_F(TeamPlanCliTest, DescriptorsWritesEachRobotsFileAsTheShippedTeamHasIt) {
  const std::string source = DVPR_SOURCE_DIR;
  std::string entries;
  for (int r = 0; r < 3; ++r) {
    entries += std::string(r ? ", " : "") + "{poses: " + source + "/data/own_team/robot" + std::to_string(r) +
               ".txt, format: tum, start: " + std::to_string(20 * r) + "s}";
  }
  const Result r = Dvpr("descriptors '" + source + "/experiments/configs/own_team.yaml' --out '" + Out().string() +
                        "' --set dataset.source=synthetic --set 'dataset.trajectories=[" + entries + "]'");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto bytes = [](const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  };
  for (int k = 0; k < 3; ++k) {
    const std::string name = "robot" + std::to_string(k) + ".npy";
    ASSERT_TRUE(fs::exists(Out() / name)) << name;
    EXPECT_EQ(bytes(Out() / name), bytes(source + "/data/own_team/" + name)) << name;
  }
  fs::remove_all(Out());
  std::ofstream(Config()) << KittiYaml("split", 2);
  const Result split = Dvpr("descriptors '" + Config().string() + "' --out '" + Out().string() + "'");
  EXPECT_EQ(split.status, 1);
  EXPECT_NE(split.err.find("dataset: dvpr descriptors writes a team plan's robots' descriptors"), std::string::npos)
      << split.err;
  EXPECT_EQ(std::count(split.err.begin(), split.err.end(), '\n'), 1) << split.err;
  EXPECT_FALSE(fs::exists(Out()));
  EXPECT_EQ(Dvpr("descriptors '" + Config().string() + "'").status, 2);
}

}  // namespace
}  // namespace dvpr::testing_support
