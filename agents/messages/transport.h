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
#include <type_traits>
#include <unordered_map>
#include <vector>

#include "agents/messages/decoded_messages.h"
#include "agents/messages/lcm_codec.h"
#include "net_models/core/payload_buffers.h"
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
  // Messages are decoded into the transport's DecodedMessages (reused once nobody holds them:
  // no allocation per message); the handler's reference is valid during the call only.
  template <typename Msg>
  [[nodiscard]] Subscription Subscribe(const std::string& channel, std::function<void(const Msg&)> handler) {
    return Subscription(this, DoSubscribe(channel, PooledDecoder<Msg, const Msg&>{this, std::move(handler)}));
  }
  // The same, with a reference the handler may keep: the message stays alive and unchanged
  // while a copy of it exists (a queued task points into it instead of copying it).
  template <typename Msg>
  [[nodiscard]] Subscription SubscribeShared(const std::string& channel,
                                             std::function<void(const MessageRef<Msg>&)> handler) {
    return Subscription(this, DoSubscribe(channel, PooledDecoder<Msg, const MessageRef<Msg>&>{this, std::move(handler)}));
  }

  // From now on messages are decoded into `decodes` (null: the transport's own), which must
  // outlive the transport and every MessageRef its handlers kept. Transports that share one and
  // name their deliveries (SimTransport: by the network's message number) decode a message
  // delivered to several of them once.
  void ShareDecodes(DecodedMessages* decodes) { decodes_ = decodes != nullptr ? decodes : &own_decodes_; }

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

  // Names the message being delivered while the transport calls its raw handlers: != 0, and
  // the same for every delivery of one published message to transports sharing a
  // DecodedMessages (see ShareDecodes); 0 (the default) names nothing.
  std::uint64_t delivery_key_ = 0;

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

  // A subscription's raw handler: the delivery's message from the transport's DecodedMessages,
  // handed to the handler as a reference to the message (Arg = const Msg&) or as a MessageRef.
  template <typename Msg, typename Arg>
  struct PooledDecoder {
    Transport* transport;
    std::function<void(Arg)> handler;

    void operator()(const std::string&, std::span<const std::uint8_t> bytes) const {
      const MessageRef<Msg> msg = transport->decodes_->Pool<Msg>().Decode(transport->delivery_key_, bytes);
      if (!msg) {
        ++transport->malformed_;
      } else if constexpr (std::is_same_v<Arg, const Msg&>) {
        handler(*msg);
      } else {
        handler(msg);
      }
    }
  };

  std::uint64_t malformed_ = 0;
  PayloadBuffers* buffers_ = nullptr;
  DecodedMessages own_decodes_;
  DecodedMessages* decodes_ = &own_decodes_;
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
