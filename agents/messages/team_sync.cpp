#include "agents/messages/team_sync.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace dvpr {

TeamSync::TeamSync(RobotId self, int robots, std::int64_t team_key)
    : self_(self), robots_(robots), team_key_(team_key),
      ready_utime_(static_cast<std::size_t>(std::max(robots, 0))),
      done_(static_cast<std::size_t>(std::max(robots, 0)), false),
      sender_(static_cast<std::size_t>(std::max(robots, 0)), 0) {
  if (robots < 1 || self.value < 0 || self.value >= robots) {
    throw std::invalid_argument("TeamSync: robot " + std::to_string(self.value) + " is not in a team of " +
                                std::to_string(robots));
  }
}

bool TeamSync::OnStatus(const agent_status_t& s, std::uint64_t sender) {
  bool ours = s.team_key == team_key_ && s.robots == robots_ && s.robot >= 0 && s.robot < robots_ &&
              s.state >= agent_status_t::READY && s.state <= agent_status_t::DONE;
  const auto r = static_cast<std::size_t>(std::max<int>(s.robot, 0));
  if (ours && sender != 0) {
    const auto known = robot_of_.find(sender);
    if (sender_[r] == 0 && known == robot_of_.end()) {
      sender_[r] = sender;
      robot_of_.emplace(sender, s.robot);
    }
    ours = sender_[r] == sender;
  }
  if (!ours) {
    ++foreign_;
    return false;
  }
  // The first ready instant heard is kept: a restarted agent must not move
  // the start the others already computed.
  if (!ready_utime_[r]) ready_utime_[r] = s.ready_utime;
  if (s.state == agent_status_t::DONE) done_[r] = true;
  return true;
}

agent_status_t TeamSync::Announce(std::int64_t utime, std::int8_t state, std::int64_t ready_utime,
                                  std::int32_t frames_taken) const {
  agent_status_t s;
  s.utime = utime;
  s.robot = static_cast<std::int16_t>(self_.value);
  s.robots = static_cast<std::int16_t>(robots_);
  s.team_key = team_key_;
  s.state = state;
  s.ready_utime = ready_utime;
  s.frames_taken = frames_taken;
  return s;
}

bool TeamSync::FromMember(RobotId robot, std::uint64_t sender) const {
  return sender != 0 && robot.value >= 0 && robot.value < robots_ &&
         sender_[static_cast<std::size_t>(robot.value)] == sender;
}

int TeamSync::HeardCount() const {
  return static_cast<int>(std::count_if(ready_utime_.begin(), ready_utime_.end(),
                                        [](const auto& t) { return t.has_value(); }));
}

std::optional<std::int64_t> TeamSync::StartUtime(std::int64_t margin_us) const {
  if (HeardCount() < robots_) return std::nullopt;
  std::int64_t latest = 0;
  for (const auto& t : ready_utime_) latest = std::max(latest, *t);
  return latest + margin_us;
}

bool TeamSync::AllDone() const {
  return std::all_of(done_.begin(), done_.end(), [](bool d) { return d; });
}

void Fnv1a::Add(const void* data, std::size_t size) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < size; ++i) {
    h_ ^= p[i];
    h_ *= 0x100000001b3ull;
  }
}

}  // namespace dvpr
