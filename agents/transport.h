#pragma once
// What a robot agent sees of the world: typed LCM messages on named channels,
// a clock and timers. Two implementations: SimTransport (virtual time, the
// simulated Network) and LcmTransport (lcm::LCM over UDP multicast, wall
// clock). Agent code is written once against this interface.
//
// Channels follow LCM's one-type-per-channel convention (see channels.h):
// unicast channels are per destination robot, broadcast has one channel.
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "agents/lcm_codec.h"
#include "sim/sim_time.h"

namespace dvpr {

class Transport;

// RAII subscription: unsubscribes when destroyed. Movable, not copyable.
class Subscription {
 public:
  Subscription() = default;
  Subscription(Transport* transport, std::uint64_t id) : transport_(transport), id_(id) {}
  Subscription(Subscription&& o) noexcept : transport_(o.transport_), id_(o.id_) { o.transport_ = nullptr; }
  Subscription& operator=(Subscription&& o) noexcept;
  Subscription(const Subscription&) = delete;
  Subscription& operator=(const Subscription&) = delete;
  ~Subscription() { Reset(); }
  void Reset();

 private:
  Transport* transport_ = nullptr;
  std::uint64_t id_ = 0;
};

class Transport {
 public:
  using RawHandler = std::function<void(const std::string& channel, std::span<const std::uint8_t> bytes)>;
  using Callback = std::function<void()>;

  virtual ~Transport() = default;

  // Encodes msg and publishes it; returns the payload size in bytes.
  template <typename Msg>
  std::size_t Publish(const std::string& channel, const Msg& msg) {
    std::vector<std::uint8_t> bytes = Encode(msg);
    const std::size_t n = bytes.size();
    DoPublish(channel, Msg::getTypeName(), std::move(bytes));
    return n;
  }

  // Calls handler with each message of type Msg received on channel. A buffer
  // that does not decode as Msg is counted in MalformedCount() and dropped.
  template <typename Msg>
  [[nodiscard]] Subscription Subscribe(const std::string& channel, std::function<void(const Msg&)> handler) {
    return Subscription(this, DoSubscribe(channel, [this, h = std::move(handler)](
                                                       const std::string&, std::span<const std::uint8_t> b) {
      if (auto msg = Decode<Msg>(b)) {
        h(*msg);
      } else {
        ++malformed_;
      }
    }));
  }

  // The agent's clock: virtual time in simulation, time since start when real.
  virtual SimTime Now() const = 0;
  // Agent time `t` as a message timestamp (utime): microseconds since the Unix epoch. In
  // simulation the run's start instant + t; when real, the wall-clock instant of t.
  virtual std::int64_t UtimeAt(SimTime t) const = 0;
  std::int64_t Utime() const { return UtimeAt(Now()); }
  // Runs fn after delay (>= 0) on the agent's own thread of control.
  virtual void ScheduleAfter(SimTime delay, Callback fn) = 0;

  std::uint64_t MalformedCount() const { return malformed_; }

 protected:
  virtual void DoPublish(const std::string& channel, const char* type_name, std::vector<std::uint8_t> bytes) = 0;
  virtual std::uint64_t DoSubscribe(const std::string& channel, RawHandler handler) = 0;
  virtual void DoUnsubscribe(std::uint64_t id) = 0;

 private:
  friend class Subscription;
  std::uint64_t malformed_ = 0;
};

inline void Subscription::Reset() {
  if (transport_ != nullptr) transport_->DoUnsubscribe(id_);
  transport_ = nullptr;
}

inline Subscription& Subscription::operator=(Subscription&& o) noexcept {
  if (this != &o) {
    Reset();
    transport_ = o.transport_;
    id_ = o.id_;
    o.transport_ = nullptr;
  }
  return *this;
}

}  // namespace dvpr
