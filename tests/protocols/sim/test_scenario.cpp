// The scenario builder (experiments/domain/scenario/scenario.h): the team's physics from
// ScenarioParams alone, with stand-in agents so every number is worked out by hand.
#include "experiments/domain/scenario/scenario.h"

#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace dvpr {
namespace {

// 5 frames at 10 fps; frame f is at (f, 0, 2f). Split among 2 robots: robot 0 drives frames
// 0..1, robot 1 frames 2..4 (docs/design.md section 2), each from t = 0.
Dataset FiveFrames() {
  Dataset d;
  d.name = "five";
  d.fps = 10.0;
  d.descriptors = DescriptorMatrix::Zero(5, 2);
  d.trajectory.positions.resize(5, 3);
  d.trajectory.headings.resize(5, 3);
  for (int f = 0; f < 5; ++f) {
    d.trajectory.positions.row(f) << f, 0.0, 2.0 * f;
    d.trajectory.headings.row(f) << 0.0, 0.0, 1.0;
  }
  return d;
}

// What the scenario did with one agent: its setup, and when it was started, woke and went offline.
struct AgentTrace {
  AgentSetup setup;
  std::vector<std::string> events;
};

// Starts, then wakes once 250 ms later; records when.
class StandInAgent final : public TeamAgent {
 public:
  StandInAgent(const AgentSetup& setup, Transport& transport, AgentTrace& trace)
      : transport_(transport), trace_(trace) {
    trace_.setup = setup;
  }
  void Start() override {
    Note("start");
    transport_.ScheduleAfter(SimTime::Millis(250), [this] { Note("wake"); });
  }
  std::vector<std::string> Inbox() const override { return {}; }
  void GoOffline() override { Note("offline"); }
  RobotId id() const override { return trace_.setup.id; }
  const std::vector<QueryRecord>& outcomes() const override { return outcomes_; }
  RobotLoad load() const override { return {}; }

 private:
  void Note(const std::string& what) { trace_.events.push_back(what + " " + std::to_string(transport_.Now().ns())); }
  Transport& transport_;
  AgentTrace& trace_;
  std::vector<QueryRecord> outcomes_;
};

class ScenarioTest : public ::testing::Test {
 protected:
  ScenarioParams Params(int robots) const {
    ScenarioParams p;
    p.robots = robots;
    p.network.model = LinkModelKind::kIdeal;
    return p;
  }
  AgentFactory Factory() {
    return [this](const AgentSetup& setup, Transport& transport) {
      return std::make_unique<StandInAgent>(setup, transport, traces[static_cast<std::size_t>(setup.id.value)]);
    };
  }
  std::string ErrorOf(const ScenarioParams& p) {
    try {
      Scenario s(data, p, Factory());
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "(no error)";
  }
  Dataset data = FiveFrames();
  std::vector<AgentTrace> traces = std::vector<AgentTrace>(3);
};

TEST_F(ScenarioTest, EachRobotGetsItsSubSequenceAndTheTeam) {
  const Scenario s(data, Params(2), Factory());
  ASSERT_EQ(s.agents().size(), 2u);
  EXPECT_EQ(traces[0].setup.id, RobotId(0));
  EXPECT_EQ(traces[0].setup.robots, 2);
  EXPECT_EQ(traces[0].setup.frames.first, FrameId(0));
  EXPECT_EQ(traces[0].setup.frames.count, 2);
  EXPECT_EQ(traces[1].setup.id, RobotId(1));
  EXPECT_EQ(traces[1].setup.frames.first, FrameId(2));
  EXPECT_EQ(traces[1].setup.frames.count, 3);
  EXPECT_EQ(traces[1].setup.frames.fps, 10.0);
  EXPECT_EQ(traces[1].setup.frames.descriptors, &data.descriptors);
  EXPECT_EQ(s.network().nodes(), 2);
  EXPECT_EQ(s.network().link().Name(), "ideal");
  EXPECT_EQ(s.network().propagation().Name(), "full_mesh");
  EXPECT_EQ(s.network().next_hop().Name(), "direct");
}

TEST_F(ScenarioTest, CaptureTimesAreEachRobotsFrameClock) {
  const Scenario s(data, Params(2), Factory());
  const std::vector<SimTime> expected{SimTime::Zero(), SimTime::Millis(100), SimTime::Zero(), SimTime::Millis(100),
                                      SimTime::Millis(200)};
  EXPECT_EQ(s.CaptureTimes(), expected);
}

TEST_F(ScenarioTest, TheRobotsMoveAlongTheirFramesPoses) {
  const Scenario s(data, Params(2), Factory());
  const MobilityModel& m = s.network().mobility();
  EXPECT_EQ(m.Name(), "track");
  EXPECT_EQ(m.PositionOf(NodeId(0), SimTime::Zero()), (Position{0, 0, 0}));
  EXPECT_EQ(m.PositionOf(NodeId(0), SimTime::Millis(50)), (Position{0.5, 0, 1}));
  EXPECT_EQ(m.PositionOf(NodeId(0), SimTime::Millis(150)), (Position{1, 0, 2}));  // its last frame: stays
  EXPECT_EQ(m.PositionOf(NodeId(1), SimTime::Millis(50)), (Position{2.5, 0, 5}));
  EXPECT_EQ(m.PositionOf(NodeId(1), SimTime::Millis(200)), (Position{4, 0, 8}));
  EXPECT_EQ(m.PositionOf(NodeId(1), SimTime::Seconds(60)), (Position{4, 0, 8}));
}

TEST_F(ScenarioTest, RunStartsEveryAgentAndTakesTheDroppedRobotOffline) {
  ScenarioParams p = Params(3);
  p.dropouts.push_back({RobotId(1), SimTime::Millis(150)});
  Scenario s(data, p, Factory());
  EXPECT_TRUE(s.IsDropped(RobotId(1)));
  EXPECT_FALSE(s.IsDropped(RobotId(0)));
  s.Run();
  EXPECT_EQ(traces[0].events, (std::vector<std::string>{"start 0", "wake 250000000"}));
  EXPECT_EQ(traces[1].events, (std::vector<std::string>{"start 0", "offline 150000000", "wake 250000000"}));
  EXPECT_EQ(traces[2].events, (std::vector<std::string>{"start 0", "wake 250000000"}));
  EXPECT_TRUE(s.network().IsOnline(NodeId(1), SimTime::Millis(149)));
  EXPECT_FALSE(s.network().IsOnline(NodeId(1), SimTime::Millis(150)));
  EXPECT_EQ(s.simulator().Now(), SimTime::Millis(250));
  EXPECT_EQ(s.simulator().EventsExecuted(), 4u);  // three wakes and one dropout
}

TEST_F(ScenarioTest, BadParamsAreRefusedNamingTheField) {
  EXPECT_EQ(ErrorOf(Params(1)), "robots: at least 2 robots are needed, got 1");
  EXPECT_EQ(ErrorOf(Params(6)), "robots: 6 robots but only 5 frames");
  ScenarioParams p = Params(2);
  p.dropouts.push_back({RobotId(2), SimTime::Zero()});
  EXPECT_EQ(ErrorOf(p), "dropout.robot: 2 is not a robot of 0..1");
  data.trajectory.positions.resize(4, 3);
  EXPECT_EQ(ErrorOf(Params(2)), "dataset: 4 poses for 5 frames (the robots drive the poses)");
}

}  // namespace
}  // namespace dvpr
