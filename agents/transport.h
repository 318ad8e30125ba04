#pragma once
// What a robot agent sees of the world: typed LCM messages on named channels,
// a clock and timers. Two implementations: SimTransport (virtual time, the
// simulated Network) and LcmTransport (lcm::LCM over UDP multicast, wall
// clock). Agent code is written once against this interface.
//
// Channels follow LCM's one-type-per-channel convention (see channels.h):
// unicast channels are per destination robot, broadcast has one channel.
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <unordered_map>
#include <vector>

#include "agents/lcm_codec.h"
#include "net_models/payload_buffers.h"
#include "sim/sim_time.h"

namespace dvpr {

class Transport;

// A channel name interned by a transport (Transport::Intern): publishing on it does not look the
// name up again, which a reply sent to one of 99 queriers per search otherwise did every time
// (hashing the name). Valid only with the transport that made it.
enum class PublishChannel : std::uint32_t {};

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
    std::vector<std::uint8_t> bytes = EncodeForPublish(msg);
    const std::size_t n = bytes.size();
    DoPublish(channel, Msg::getTypeName(), std::move(bytes));
    return n;
  }
  // The same on a channel interned before: no name lookup per message.
  template <typename Msg>
  std::size_t Publish(PublishChannel channel, const Msg& msg) {
    std::vector<std::uint8_t> bytes = EncodeForPublish(msg);
    const std::size_t n = bytes.size();
    DoPublishInterned(channel, Msg::getTypeName(), std::move(bytes));
    return n;
  }

  // The channel `name` to publish on; the same name gives the same value every time.
  PublishChannel Intern(const std::string& name) { return DoIntern(name); }
  // The name of an interned channel (valid as long as the transport).
  const std::string& NameOf(PublishChannel channel) const { return DoNameOf(channel); }

  // From now on messages are encoded into buffers taken from `buffers` (the simulated network's,
  // Network::payload_buffers(), which gets them back when delivered) instead of new ones. It
  // must outlive the transport; null: a new buffer per message.
  void UseBuffers(PayloadBuffers* buffers) { buffers_ = buffers; }

  // Calls handler with each message of type Msg received on channel. A buffer
  // that does not decode as Msg is counted in MalformedCount() and dropped.
  // Each subscription decodes into one message of its own, reused from delivery to delivery
  // (no allocation per message); the handler's reference is valid during the call only.
  template <typename Msg>
  [[nodiscard]] Subscription Subscribe(const std::string& channel, std::function<void(const Msg&)> handler) {
    return Subscription(this, DoSubscribe(channel, ReusingDecoder<Msg>{this, std::move(handler)}));
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
  // Publishing on an interned channel: by its name unless the transport has a faster way.
  virtual void DoPublishInterned(PublishChannel channel, const char* type_name, std::vector<std::uint8_t> bytes) {
    DoPublish(NameOf(channel), type_name, std::move(bytes));
  }
  // Interning: a table of the transport's own unless the transport has one already (the
  // simulated network's, shared by every agent: a name is stored once, not once an agent).
  virtual PublishChannel DoIntern(const std::string& name);
  virtual const std::string& DoNameOf(PublishChannel channel) const {
    return interned_.at(static_cast<std::size_t>(channel));
  }
  virtual std::uint64_t DoSubscribe(const std::string& channel, RawHandler handler) = 0;
  virtual void DoUnsubscribe(std::uint64_t id) = 0;

 private:
  friend class Subscription;

  // msg's encoding, in a buffer from the pool when there is one.
  template <typename Msg>
  std::vector<std::uint8_t> EncodeForPublish(const Msg& msg) {
    std::vector<std::uint8_t> bytes;
    if (buffers_ != nullptr) bytes = buffers_->Take(static_cast<std::size_t>(msg.getEncodedSize()));
    EncodeInto(msg, bytes);
    return bytes;
  }

  // A subscription's raw handler: decodes into its own message. A handler that is called again
  // while the message is in use (a transport that delivers from inside a handler) decodes into a
  // message of that call's own. The message lives in the decoder itself, not behind a pointer of
  // its own: one cache line less to fetch per delivery. RawHandler may copy the decoder; a copy
  // starts with a message of its own (what it holds between calls is never read).
  template <typename Msg>
  struct ReusingDecoder {
    struct Reused {
      Msg msg;
      bool in_use = false;
      Reused() = default;
      Reused(const Reused&) {}
      Reused& operator=(const Reused&) { return *this; }
    };
    Transport* transport;
    std::function<void(const Msg&)> handler;
    mutable Reused reused{};

    void operator()(const std::string&, std::span<const std::uint8_t> bytes) const {
      if (reused.in_use) {
        Msg own;
        Deliver(bytes, own);
        return;
      }
      reused.in_use = true;
      struct Release {
        bool& in_use;
        ~Release() { in_use = false; }
      } release{reused.in_use};
      Deliver(bytes, reused.msg);
    }
    void Deliver(std::span<const std::uint8_t> bytes, Msg& into) const {
      if (DecodeInto(bytes, into)) {
        handler(into);
      } else {
        ++transport->malformed_;
      }
    }
  };

  std::uint64_t malformed_ = 0;
  PayloadBuffers* buffers_ = nullptr;
  std::deque<std::string> interned_;  // by PublishChannel; deque: NameOf's references stay put
  std::unordered_map<std::string, std::uint32_t> interned_ids_;
};

inline PublishChannel Transport::DoIntern(const std::string& name) {
  const auto [it, added] = interned_ids_.try_emplace(name, static_cast<std::uint32_t>(interned_.size()));
  if (added) interned_.push_back(name);
  return PublishChannel{it->second};
}

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
