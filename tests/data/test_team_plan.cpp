// Team plans (experiments/domain/data/team_plan.h, docs/design.md section 3 "Team plans"): which rows
// each robot drives, when it takes each and which frames its window suppresses, worked by hand on
// small sequences.
#include "experiments/domain/data/team_plan.h"

#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "experiments/domain/data/synthetic.h"

namespace dvpr {
namespace {

// A straight 10-frame drive along x, a metre a frame, facing +z.
Trajectory Line(int frames) {
  Trajectory t;
  t.positions = Positions::Zero(frames, 3);
  t.headings = Headings::Zero(frames, 3);
  for (int i = 0; i < frames; ++i) {
    t.positions(i, 0) = i;
    t.headings(i, 2) = 1.0;
  }
  return t;
}

std::vector<std::int32_t> Rows(std::initializer_list<std::int32_t> r) { return r; }

TEST(TeamPlanTest, StaggeredDrivesTheWholeSequenceOffsetByRobot) {
  const ScenarioSpec spec{ScenarioKind::kStaggered, 60.0, 0, 1};
  const std::vector<RobotDrive> d = PlanDrives(spec, 4, 3, 10.0);
  ASSERT_EQ(d.size(), 3u);
  for (int r = 0; r < 3; ++r) {
    EXPECT_EQ(d[r].rows, Rows({0, 1, 2, 3})) << r;
    EXPECT_FALSE(d[r].backwards);
    EXPECT_DOUBLE_EQ(d[r].start_s, 60.0 * r);
  }
  const Dataset team = DriveTeam(Line(4), d, 10.0);
  ASSERT_TRUE(team.plan.has_value());
  const SequenceSplit& p = *team.plan;
  ASSERT_EQ(p.frames(), 12);
  EXPECT_EQ(p.ranges[1].begin, FrameId(4));
  EXPECT_EQ(p.ranges[2].end, FrameId(12));
  // Robot 2's third frame (row 10 of the team, pose 2) at 120 s + 2 / 10 s.
  EXPECT_EQ(p.capture[10], SimTime::Millis(120200));
  EXPECT_EQ(p.OwnerOf(FrameId(10)), RobotId(2));
  EXPECT_DOUBLE_EQ(team.trajectory.positions(10, 0), 2.0);
  // Robot 1's stream: first frame 4, four frames, at 60.0, 60.1, 60.2, 60.3 s.
  const FrameStream s = p.StreamOf(1, nullptr, 10.0);
  EXPECT_EQ(s.first, FrameId(4));
  EXPECT_EQ(s.count, 4);
  EXPECT_EQ(s.TimeOf(0), SimTime::Seconds(60));
  EXPECT_EQ(s.TimeOf(3), SimTime::Millis(60300));
  // Frames in periods of the common clock: 60.3 s x 10 fps = 603.
  EXPECT_NEAR(TimesInFrames(p, 10.0)[7], 603.0, 1e-9);
}

TEST(TeamPlanTest, ReverseDrivesEveryOtherRobotBackwardsFacingTheOtherWay) {
  const std::vector<RobotDrive> d = PlanDrives({ScenarioKind::kReverse, 0.0, 0, 1}, 3, 3, 10.0);
  EXPECT_EQ(d[0].rows, Rows({0, 1, 2}));
  EXPECT_EQ(d[1].rows, Rows({2, 1, 0}));
  EXPECT_TRUE(d[1].backwards);
  EXPECT_EQ(d[2].rows, Rows({0, 1, 2}));
  EXPECT_DOUBLE_EQ(d[1].start_s, 0.0);
  const Dataset team = DriveTeam(Line(3), d, 10.0);
  // Robot 1's first frame (team row 3) is pose 2, at x = 2, facing -z, taken at 0 s.
  EXPECT_DOUBLE_EQ(team.trajectory.positions(3, 0), 2.0);
  EXPECT_DOUBLE_EQ(team.trajectory.headings(3, 2), -1.0);
  EXPECT_DOUBLE_EQ(team.trajectory.headings(0, 2), 1.0);
  EXPECT_EQ(team.plan->capture[3], SimTime::Zero());
  // With an offset robot r starts r x offset later.
  EXPECT_DOUBLE_EQ(PlanDrives({ScenarioKind::kReverse, 5.0, 0, 1}, 3, 3, 10.0)[2].start_s, 10.0);
}

TEST(TeamPlanTest, RandomRoutesAreSeededStretchesInsideTheSequence) {
  const ScenarioSpec spec{ScenarioKind::kRandomRoutes, 0.0, 5, 7};
  const std::vector<RobotDrive> a = PlanDrives(spec, 20, 4, 10.0);
  const std::vector<RobotDrive> b = PlanDrives(spec, 20, 4, 10.0);
  bool differ = false;
  for (std::size_t r = 0; r < a.size(); ++r) {
    EXPECT_EQ(a[r].rows, b[r].rows);  // same seed, same routes
    EXPECT_EQ(a[r].start_s, b[r].start_s);
    ASSERT_EQ(a[r].rows.size(), 5u);
    for (std::size_t k = 1; k < 5; ++k) EXPECT_EQ(a[r].rows[k], a[r].rows[0] + static_cast<std::int32_t>(k));
    EXPECT_GE(a[r].rows.front(), 0);
    EXPECT_LE(a[r].rows.back(), 19);
    // Started in [0, (20 - 5) / 10 s].
    EXPECT_GE(a[r].start_s, 0.0);
    EXPECT_LE(a[r].start_s, 1.5);
    differ = differ || a[r].rows != a[0].rows;
  }
  EXPECT_TRUE(differ) << "four robots drew the same stretch";
  const std::vector<RobotDrive> c = PlanDrives({ScenarioKind::kRandomRoutes, 0.0, 5, 8}, 20, 4, 10.0);
  bool other_seed_differs = false;
  for (std::size_t r = 0; r < a.size(); ++r) other_seed_differs = other_seed_differs || c[r].rows != a[r].rows;
  EXPECT_TRUE(other_seed_differs);
  // A whole-sequence stretch has one place to start: frame 0, at time 0.
  const std::vector<RobotDrive> whole = PlanDrives({ScenarioKind::kRandomRoutes, 0.0, 20, 3}, 20, 2, 10.0);
  EXPECT_EQ(whole[1].rows.front(), 0);
  EXPECT_EQ(whole[1].start_s, 0.0);
}

TEST(TeamPlanTest, BadScenariosAreNamedErrors) {
  const auto message = [](const ScenarioSpec& s, int frames) {
    try {
      PlanDrives(s, frames, 2, 10.0);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message({ScenarioKind::kStaggered, 0.0, 0, 1}, 10),
            "offset: staggered needs a positive offset (robot r starts r x offset later)");
  EXPECT_EQ(message({ScenarioKind::kRandomRoutes, 0.0, 0, 1}, 10),
            "length: random_routes needs each stretch's length in frames, at least 2");
  EXPECT_EQ(message({ScenarioKind::kRandomRoutes, 0.0, 11, 1}, 10), "length: 11 frames, the sequence has 10");
  EXPECT_EQ(message({ScenarioKind::kStaggered, 5.0, 4, 1}, 10), "length: only random_routes takes a length, not staggered");
  EXPECT_EQ(message({ScenarioKind::kRandomRoutes, 5.0, 4, 1}, 10),
            "offset: only staggered and reverse take an offset, not random_routes");
  EXPECT_EQ(message({ScenarioKind::kSplit, 0.0, 0, 1}, 10), "scenario split is the paper's split, not a team plan");
  EXPECT_THROW(ParseScenarioKind("zigzag"), std::invalid_argument);
  EXPECT_EQ(ParseScenarioKind("random_routes"), ScenarioKind::kRandomRoutes);
  EXPECT_THROW(PlannedSplit({{SimTime::Seconds(1)}, {}}), std::invalid_argument);
  EXPECT_THROW(PlannedSplit({{SimTime::Seconds(2), SimTime::Seconds(1)}}), std::invalid_argument);
}

TEST(TeamPlanTest, TrajectoriesKeepTheirOwnTimesFromTheirStart) {
  TrajectorySource a, b;
  a.format = b.format = TrajectoryFormat::kTum;
  b.start_s = 30.0;
  TimedTrajectory ta{Line(2), {0.0, 0.5}};
  TimedTrajectory tb{Line(3), {0.0, 2.0, 2.25}};
  const Dataset team = TeamOfTrajectories({a, b}, {ta, tb}, 10.0);
  const SequenceSplit& p = *team.plan;
  ASSERT_EQ(p.frames(), 5);
  const std::vector<SimTime> want{SimTime::Zero(), SimTime::Millis(500), SimTime::Seconds(30), SimTime::Seconds(32),
                                  SimTime::Millis(32250)};
  EXPECT_EQ(p.capture, want);
  EXPECT_EQ(p.WindowStreams(), std::vector<FrameId>{FrameId(2)});
  b.frame = "map";
  EXPECT_THROW(TeamOfTrajectories({a, b}, {ta, tb}, 10.0), std::invalid_argument);
}

TEST(TeamPlanTest, TheWindowStaysInsideEachRobotsStream) {
  // Robots' streams [0, 4), [4, 12), [12, 14); window 3.
  const std::vector<std::vector<SimTime>> times{std::vector<SimTime>(4), std::vector<SimTime>(8),
                                                std::vector<SimTime>(2)};
  const FrameWindow w = PlannedSplit(times).Window(3);
  // Frame 3 (robot 0's last): 0..3, not robot 1's 4..6.
  EXPECT_EQ(w.Around(3).lo, 0);
  EXPECT_EQ(w.Around(3).hi, 3);
  // Frame 5: 4..8 (robot 1 from 4, not robot 0's 2, 3).
  EXPECT_EQ(w.Around(5).lo, 4);
  EXPECT_EQ(w.Around(5).hi, 8);
  EXPECT_FALSE(w.Suppresses(5, 3));
  EXPECT_TRUE(w.Suppresses(5, 8));
  EXPECT_FALSE(w.Suppresses(5, 9));
  // Frame 12 (robot 2's first): from 12 (not robot 1's 9..11) to 15 (the last stream runs on; no
  // frame lies past 13).
  EXPECT_EQ(w.Around(12).lo, 12);
  EXPECT_EQ(w.Around(12).hi, 15);
  // The paper's split: one stream, |i - j| <= 3 across robots.
  const FrameWindow split = SplitSequence(14, 3).Window(3);
  EXPECT_TRUE(split.Suppresses(5, 3));
  EXPECT_EQ(split.Around(12).lo, 9);
  EXPECT_EQ(split.Around(12).hi, 15);
}

TEST(TeamPlanTest, SyntheticTimesOfTheFrameIndexGiveTheSplitsDescriptors) {
  const Trajectory line = Line(30);
  SyntheticParams params;
  params.dim = 8;
  std::vector<double> index(30);
  for (int i = 0; i < 30; ++i) index[static_cast<std::size_t>(i)] = i;
  const DescriptorMatrix a = SyntheticDeployment(line, params, 5);
  const DescriptorMatrix b = SyntheticDeployment(line, index, params, 5);
  EXPECT_EQ(a, b);
  // Another clock changes only the appearance term: the descriptors move.
  index[10] += 500.0;
  const DescriptorMatrix c = SyntheticDeployment(line, index, params, 5);
  EXPECT_NE(c.row(10), a.row(10));
  EXPECT_EQ(c.row(11), a.row(11));
}

}  // namespace
}  // namespace dvpr
