#include "experiments/domain/scenario/scenario.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

#include "agents/algorithms/frame_stream.h"
#include "net_models/helper/network_helper.h"
#include "net_models/link_state/daemon/link_state_helper.h"

namespace dvpr {

void ScenarioParams::Validate(const Dataset& data) const {
  if (robots < 2) throw std::invalid_argument("robots: at least 2 robots are needed, got " + std::to_string(robots));
  if (robots > data.size()) {
    throw std::invalid_argument("robots: " + std::to_string(robots) + " robots but only " +
                                std::to_string(data.size()) + " frames");
  }
  if (robots > kMaxWireInt16) throw std::invalid_argument("robots: at most 32767 (int16 robot ids on the wire)");
  if (data.dim() > kMaxWireInt16) {
    throw std::invalid_argument("dataset.dim: at most 32767 values per descriptor (query_t's int16 dim), got " +
                                std::to_string(data.dim()));
  }
  if (data.trajectory.size() != data.size()) {
    throw std::invalid_argument("dataset: " + std::to_string(data.trajectory.size()) + " poses for " +
                                std::to_string(data.size()) + " frames (the robots drive the poses)");
  }
  if (data.plan && data.plan->robots() != robots) {
    throw std::invalid_argument("robots: the team plan of the dataset is for " + std::to_string(data.plan->robots()) +
                                " robots, the run has " + std::to_string(robots));
  }
  agent.Validate();
  network.Validate(robots);
  for (const auto& d : dropouts) {
    if (d.robot.value < 0 || d.robot.value >= robots) {
      throw std::invalid_argument("dropout.robot: " + std::to_string(d.robot.value) + " is not a robot of 0.." +
                                  std::to_string(robots - 1));
    }
  }
}

namespace {

const ScenarioParams& Validated(const ScenarioParams& params, const Dataset& data) {
  params.Validate(data);
  return params;
}

}  // namespace

TrackMobility RobotTracks(const Dataset& data, const SequenceSplit& split) {
  std::vector<std::vector<Waypoint>> tracks(split.ranges.size());
  for (int r = 0; r < split.robots(); ++r) {
    const FrameStream frames = split.StreamOf(r, nullptr, data.fps);
    for (int k = 0; k < frames.count; ++k) {
      const auto row = data.trajectory.positions.row(frames.first.value + k);
      tracks[static_cast<std::size_t>(r)].push_back(Waypoint{frames.TimeOf(k), Position{row(0), row(1), row(2)}});
    }
  }
  return TrackMobility(std::move(tracks));
}

Scenario::Scenario(const Dataset& data, const ScenarioParams& params, const AgentFactory& make_agent)
    : data_(data),
      params_(Validated(params, data)),
      split_(TeamSplit(data, params.robots)),
      network_(sim_, params.robots,
               MakeNetworkStack(params.network, params.robots, params.seed,
                                std::make_unique<TrackMobility>(RobotTracks(data, split_))),
               WireOf(params.network)) {
  for (int r = 0; r < params_.robots; ++r) {
    auto& transport = transports_.emplace_back(std::make_unique<SimTransport>(network_, NodeId(r), params_.start_utime));
    transport->UseBuffers(&network_.payload_buffers());
    transport->ShareDecodes(&decoded_);
    const AgentSetup setup{RobotId(r), params_.robots, params_.agent, split_.StreamOf(r, &data_.descriptors, data_.fps),
                           split_.WindowStreams()};
    agents_.push_back(make_agent(setup, *transport));
  }
  std::vector<Transport*> transports;
  for (const auto& t : transports_) transports.push_back(t.get());
  daemons_ = LinkStateHelper::Install(network_, transports, split_.LastCapture(data_.fps));
}

void Scenario::Run() {
  for (auto& daemon : daemons_) daemon->Start();
  for (auto& agent : agents_) agent->Start();
  for (const auto& w : params_.talk_windows) network_.SetTalkWindows(NodeId(w.robot.value), w.windows);
  // Store-and-forward retries end with the mission: after the last frame the robots stand still
  // and the beacons stop; only a talk window's opening or closing can still change a way.
  SimTime horizon = split_.LastCapture(data_.fps);
  for (const auto& w : params_.talk_windows) {
    for (const TalkWindow& window : w.windows) {
      horizon = std::max(horizon, window.from);
      if (window.until != SimTime::Max()) horizon = std::max(horizon, window.until);
    }
  }
  network_.SetHoldHorizon(horizon);
  for (const auto& d : params_.dropouts) {
    network_.SetOffline(NodeId(d.robot.value), d.at);
    TeamAgent* agent = agents_[static_cast<std::size_t>(d.robot.value)].get();
    sim_.ScheduleAt(d.at, [agent] { agent->GoOffline(); });
  }
  sim_.Run();
}

bool Scenario::IsDropped(RobotId robot) const {
  for (const auto& d : params_.dropouts) {
    if (d.robot == robot) return true;
  }
  return false;
}

std::vector<SimTime> Scenario::CaptureTimes() const { return split_.CaptureTimes(data_.fps); }

}  // namespace dvpr
