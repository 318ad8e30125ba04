#include "agents/lcm_transport.h"

#include <poll.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <stdexcept>

namespace dvpr {

namespace {

std::int64_t SystemUtime(std::chrono::system_clock::time_point t) {
  return std::chrono::duration_cast<std::chrono::microseconds>(t.time_since_epoch()).count();
}

}  // namespace

LcmTransport::LcmTransport(const std::string& url, double speedup)
    : lcm_(url), speedup_(speedup), zero_(WallClock::now()), zero_utime_(SystemUtime(std::chrono::system_clock::now())) {
  if (!(speedup > 0.0) || !std::isfinite(speedup)) {
    throw std::invalid_argument("LcmTransport: speedup must be a positive number");
  }
  if (!lcm_.good()) {
    throw std::runtime_error("LCM could not be initialised with URL '" + url +
                             "' (for loopback multicast the interface needs multicast enabled and a route "
                             "for 224.0.0.0/4, see README)");
  }
}

LcmTransport::~LcmTransport() {
  for (auto& [channel, sub] : channels_) lcm_.unsubscribe(sub.subscription);
}

LcmTransport::WallClock::duration LcmTransport::ToWall(SimTime agent) const {
  const double ns = static_cast<double>(agent.ns()) / speedup_;
  return std::chrono::duration_cast<WallClock::duration>(std::chrono::nanoseconds(std::llround(ns)));
}

SimTime LcmTransport::Now() const {
  const auto wall = std::chrono::duration_cast<std::chrono::nanoseconds>(WallClock::now() - zero_);
  return SimTime::Nanos(std::llround(static_cast<double>(wall.count()) * speedup_));
}

void LcmTransport::SetEpoch(std::chrono::system_clock::time_point epoch) {
  // steady_clock cannot be set, system_clock can: convert once, now.
  const auto from_now = epoch - std::chrono::system_clock::now();
  zero_ = WallClock::now() + std::chrono::duration_cast<WallClock::duration>(from_now);
  zero_utime_ = SystemUtime(epoch);
}

std::int64_t LcmTransport::UtimeAt(SimTime t) const {
  return zero_utime_ + std::llround(static_cast<double>(t.ns()) / speedup_ / 1000.0);
}

void LcmTransport::ScheduleAfter(SimTime delay, Callback fn) {
  const std::uint64_t id = next_id_++;
  const WallClock::time_point base = std::max(running_due_.value_or(WallClock::now()), zero_);
  timers_.push(Timer{base + ToWall(std::max(delay, SimTime::Zero())), id});
  timer_callbacks_.emplace(id, std::move(fn));
}

void LcmTransport::DoPublish(const std::string& channel, const char*, std::vector<std::uint8_t> bytes) {
  if (lcm_.publish(channel, bytes.data(), static_cast<unsigned>(bytes.size())) != 0) {
    ++publish_failures_;  // a full socket buffer: the message is lost, like a dropped packet
    return;
  }
  ++published_;
  published_bytes_ += bytes.size();
  if (on_publish_) on_publish_(channel, bytes);
}

lcm::Subscription* LcmTransport::Listen(const std::string& channel) {
  // LCM treats the channel as a regular expression; ours are plain names.
  lcm::Subscription* s = lcm_.subscribeFunction(channel, &LcmTransport::OnRaw, this);
  if (s == nullptr) throw std::runtime_error("LCM: cannot subscribe to " + channel);
  return s;
}

void LcmTransport::HoldUntilSubscribed(const std::vector<std::string>& channels) {
  for (const std::string& channel : channels) {
    ChannelSubscription& sub = channels_[channel];
    if (sub.subscription == nullptr) sub.subscription = Listen(channel);
    sub.hold = sub.handlers.empty();
  }
}

std::uint64_t LcmTransport::DoSubscribe(const std::string& channel, RawHandler handler) {
  const std::uint64_t id = next_id_++;
  ChannelSubscription& sub = channels_[channel];
  if (sub.subscription == nullptr) sub.subscription = Listen(channel);
  sub.handlers.emplace(id, std::move(handler));
  channel_of_.emplace(id, channel);
  if (sub.hold) {
    sub.hold = false;
    if (!sub.held.empty()) {
      // Handled from the loop, not from inside Subscribe: the subscriber may not be ready yet.
      ScheduleAfter(SimTime::Zero(), [this, channel, held = std::move(sub.held)] {
        for (const auto& bytes : held) Dispatch(channel, bytes);
      });
      sub.held.clear();
    }
  }
  return id;
}

void LcmTransport::DoUnsubscribe(std::uint64_t id) {
  const auto it = channel_of_.find(id);
  if (it == channel_of_.end()) return;
  const auto sub = channels_.find(it->second);
  sub->second.handlers.erase(id);
  if (sub->second.handlers.empty()) {
    lcm_.unsubscribe(sub->second.subscription);
    channels_.erase(sub);
  }
  channel_of_.erase(it);
}

void LcmTransport::OnRaw(const lcm::ReceiveBuffer* rbuf, const std::string& channel, LcmTransport* self) {
  const std::span<const std::uint8_t> bytes(static_cast<const std::uint8_t*>(rbuf->data), rbuf->data_size);
  self->Dispatch(channel, bytes);
}

void LcmTransport::Dispatch(const std::string& channel, std::span<const std::uint8_t> bytes) {
  if (const auto held = channels_.find(channel); held != channels_.end() && held->second.hold) {
    held->second.held.emplace_back(bytes.begin(), bytes.end());  // counted when handled
    return;
  }
  ++received_;
  if (on_receive_ && !on_receive_(channel, bytes)) return;
  const auto sub = channels_.find(channel);
  if (sub == channels_.end()) return;
  // A handler may unsubscribe (itself or others): call copies, skip removed ones.
  std::vector<std::uint64_t> ids;
  for (const auto& [id, fn] : sub->second.handlers) ids.push_back(id);
  for (std::uint64_t id : ids) {
    const auto again = channels_.find(channel);
    if (again == channels_.end()) return;
    const auto h = again->second.handlers.find(id);
    if (h == again->second.handlers.end()) continue;
    RawHandler fn = h->second;
    fn(channel, bytes);
  }
}

void LcmTransport::RunDueTimers() {
  while (!timers_.empty() && !stopped_ && timers_.top().due <= WallClock::now()) {
    const Timer t = timers_.top();
    timers_.pop();
    auto it = timer_callbacks_.find(t.seq);
    Callback fn = std::move(it->second);
    timer_callbacks_.erase(it);
    running_due_ = t.due;
    try {
      fn();
    } catch (...) {
      running_due_.reset();
      throw;
    }
    running_due_.reset();
  }
}

// Waits up to `wait` for a message and handles at most one.
void LcmTransport::WaitAndHandle(WallClock::duration wait) {
  const int fd = lcm_.getFileno();
  if (fd < 0) throw std::runtime_error("LCM: no file descriptor to wait on");
  const auto ns = std::chrono::duration_cast<std::chrono::nanoseconds>(std::max(wait, WallClock::duration::zero()));
  timespec timeout{static_cast<time_t>(ns.count() / 1000000000), static_cast<long>(ns.count() % 1000000000)};
  pollfd pfd{fd, POLLIN, 0};
  const int ready = ppoll(&pfd, 1, &timeout, nullptr);
  if (ready < 0) {
    if (errno == EINTR) return;
    throw std::runtime_error(std::string("LCM: poll failed: ") + std::strerror(errno));
  }
  if (ready > 0 && lcm_.handle() != 0) throw std::runtime_error("LCM: handle failed");
}

bool LcmTransport::RunUntilWall(WallClock::time_point deadline) {
  while (!stopped_) {
    RunDueTimers();
    if (stopped_) break;
    const auto now = WallClock::now();
    if (now >= deadline) return false;
    auto wait = deadline - now;
    if (!timers_.empty()) wait = std::min(wait, timers_.top().due - now);
    WaitAndHandle(wait);
  }
  return true;
}

bool LcmTransport::Run(SimTime deadline) {
  if (deadline == SimTime::Max()) return RunUntilWall(WallClock::time_point::max());
  return RunUntilWall(zero_ + ToWall(deadline));
}

}  // namespace dvpr
