#include "agents/lcm_transport.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace dvpr {

LcmTransport::LcmTransport(const std::string& url, double speedup)
    : lcm_(url), speedup_(speedup), start_(std::chrono::steady_clock::now()) {
  if (!lcm_.good()) {
    throw std::runtime_error("LCM could not be initialised with URL '" + url +
                             "' (for loopback multicast the interface needs multicast enabled and a route "
                             "for 224.0.0.0/4, see README)");
  }
  if (!(speedup > 0.0)) throw std::invalid_argument("LcmTransport: speedup must be positive");
}

LcmTransport::~LcmTransport() {
  for (auto& [id, h] : handlers_) lcm_.unsubscribe(h->subscription);
}

SimTime LcmTransport::Now() const {
  const auto wall = std::chrono::steady_clock::now() - start_;
  const double ns = static_cast<double>(std::chrono::duration_cast<std::chrono::nanoseconds>(wall).count());
  return SimTime::Nanos(std::llround(ns * speedup_));
}

void LcmTransport::ScheduleAfter(SimTime delay, Callback fn) {
  const std::uint64_t id = next_id_++;
  timers_.push(Timer{Now() + std::max(delay, SimTime::Zero()), id});
  timer_callbacks_.emplace(id, std::move(fn));
}

void LcmTransport::DoPublish(const std::string& channel, const char*, std::vector<std::uint8_t> bytes) {
  if (lcm_.publish(channel, bytes.data(), static_cast<unsigned>(bytes.size())) == 0) {
    ++published_;
    published_bytes_ += bytes.size();
  }
}

std::uint64_t LcmTransport::DoSubscribe(const std::string& channel, RawHandler handler) {
  const std::uint64_t id = next_id_++;
  auto h = std::make_unique<Handler>(Handler{this, std::move(handler), nullptr});
  h->subscription = lcm_.subscribeFunction(channel, &LcmTransport::OnRaw, h.get());
  handlers_.emplace(id, std::move(h));
  return id;
}

void LcmTransport::DoUnsubscribe(std::uint64_t id) {
  const auto it = handlers_.find(id);
  if (it == handlers_.end()) return;
  lcm_.unsubscribe(it->second->subscription);
  handlers_.erase(it);
}

void LcmTransport::OnRaw(const lcm::ReceiveBuffer* rbuf, const std::string& channel, Handler* handler) {
  ++handler->self->received_;
  handler->fn(channel, std::span(static_cast<const std::uint8_t*>(rbuf->data), rbuf->data_size));
}

void LcmTransport::RunDueTimers() {
  while (!timers_.empty() && timers_.top().when <= Now() && !stopped_) {
    const Timer t = timers_.top();
    timers_.pop();
    auto it = timer_callbacks_.find(t.seq);
    Callback fn = std::move(it->second);
    timer_callbacks_.erase(it);
    fn();
  }
}

bool LcmTransport::Run(SimTime deadline) {
  while (!stopped_) {
    RunDueTimers();
    if (stopped_) break;
    const SimTime now = Now();
    if (now >= deadline) return false;
    SimTime wait = deadline - now;
    if (!timers_.empty()) wait = std::min(wait, timers_.top().when - now);
    // Agent time runs `speedup_` times faster than the wall clock.
    const double wall_ms = std::max(0.0, wait.ToMillis() / speedup_);
    const int timeout_ms = static_cast<int>(std::min(std::ceil(wall_ms), 100.0));
    if (lcm_.handleTimeout(timeout_ms) < 0) throw std::runtime_error("LCM: handleTimeout failed");
  }
  return true;
}

}  // namespace dvpr
