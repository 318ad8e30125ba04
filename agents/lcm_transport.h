#pragma once
// Transport over real LCM (UDP multicast by default): the same agents, run as
// processes in wall-clock time. Timers and message handlers run on the thread
// that calls Run(), so agent code needs no locks, as in the simulator.
#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <queue>
#include <string>
#include <vector>

#include <lcm/lcm-cpp.hpp>

#include "agents/transport.h"

namespace dvpr {

class LcmTransport final : public Transport {
 public:
  // url: an LCM provider URL, e.g. "udpm://239.255.76.67:7667?ttl=0"; empty
  // uses LCM's default (or $LCM_DEFAULT_URL). speedup > 1 runs the agent's
  // clock faster than the wall clock (frames at fps x speedup).
  // Throws std::runtime_error when LCM cannot be initialised.
  explicit LcmTransport(const std::string& url, double speedup = 1.0);
  ~LcmTransport() override;

  SimTime Now() const override;
  void ScheduleAfter(SimTime delay, Callback fn) override;

  // Handles messages and timers until Stop() is called or `deadline` (agent
  // clock) passes. Returns false when it stopped at the deadline.
  bool Run(SimTime deadline);
  void Stop() { stopped_ = true; }

  std::uint64_t Published() const { return published_; }
  std::uint64_t PublishedBytes() const { return published_bytes_; }
  std::uint64_t Received() const { return received_; }

 private:
  struct Timer {
    SimTime when;
    std::uint64_t seq;
    bool operator>(const Timer& o) const { return when != o.when ? when > o.when : seq > o.seq; }
  };
  struct Handler {
    LcmTransport* self;
    RawHandler fn;
    lcm::Subscription* subscription;
  };

  void DoPublish(const std::string& channel, const char* type_name, std::vector<std::uint8_t> bytes) override;
  std::uint64_t DoSubscribe(const std::string& channel, RawHandler handler) override;
  void DoUnsubscribe(std::uint64_t id) override;
  static void OnRaw(const lcm::ReceiveBuffer* rbuf, const std::string& channel, Handler* handler);
  void RunDueTimers();

  lcm::LCM lcm_;
  double speedup_;
  std::chrono::steady_clock::time_point start_;
  std::priority_queue<Timer, std::vector<Timer>, std::greater<>> timers_;
  std::map<std::uint64_t, Callback> timer_callbacks_;
  std::map<std::uint64_t, std::unique_ptr<Handler>> handlers_;
  std::uint64_t next_id_ = 1;
  bool stopped_ = false;
  std::uint64_t published_ = 0;
  std::uint64_t published_bytes_ = 0;
  std::uint64_t received_ = 0;
};

}  // namespace dvpr
