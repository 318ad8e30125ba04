#pragma once
// What the Network reports while it works, for whoever wants to record it
// (ns-3's traced callbacks on a net device, SimGrid's signals): messages.csv
// rows, an LCM event log, a test's expectations. The Network itself writes
// nothing; it only calls the observers subscribed to it (Network::Subscribe).
//
// Every copy of a message (one per destination) is reported sent once, at its
// send time, then delivered or dropped once - or neither, if the run ends
// while it is in flight. A copy the link refuses or loses, that has no route
// or is not heard (network_stack.h), or that an offline sender never puts on
// the medium, is reported dropped right after its send;
// one that reaches an offline receiver, at its arrival time.
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "net_models/core/node_id.h"
#include "net_models/core/transmission.h"
#include "sim/sim_time.h"

namespace dvpr {

// Channel and message type names, interned by the Network.
enum class ChannelId : std::uint32_t {};
enum class MessageTypeId : std::uint32_t {};

// One copy of a message, as every hook sees it. The views are valid during
// the call only.
struct MessageCopy {
  std::uint64_t message = 0;  // the network's Send/SendTo calls, numbered from 0
  std::uint64_t copy = 0;     // copies of all messages, numbered from 0 in send order
  SimTime sent;
  NodeId src;
  NodeId dst;
  ChannelId channel{};
  std::string_view channel_name;
  MessageTypeId type{};
  std::string_view type_name;
  std::span<const std::uint8_t> payload;  // the encoded message, as sent
  std::int64_t wire_bytes = 0;            // what one copy costs on the wire (wire_format.h)
  // Transmissions the copy completed: 0 when sent; when delivered, the hops it took (1 straight
  // to its destination, more through relays); when dropped, those it had made before.
  int hops = 0;
};

// What one message put on the medium (LinkModel::MediumUse), reported once per Send/SendTo
// call that had a destination, after the OnSent of its copies: a point-to-point message costs
// one transmission per copy, a shared-medium broadcast one for all. An offline sender's message
// reports none (0 bytes). The view is valid during the call only.
struct MediumReport {
  std::uint64_t message = 0;  // as MessageCopy::message
  SimTime sent;
  NodeId src;
  ChannelId channel{};
  std::string_view channel_name;
  std::uint64_t transmissions = 0;
  std::int64_t bytes = 0;     // frame bytes that went on the medium
};

// Override what you need. Hooks run inside the simulation: they must not
// send, nor subscribe or unsubscribe observers.
class NetworkObserver {
 public:
  virtual ~NetworkObserver() = default;
  virtual void OnSent(const MessageCopy& /*copy*/) {}
  // At the arrival time, before the receiver's NetworkEndpoint gets it.
  virtual void OnDelivered(const MessageCopy& /*copy*/, SimTime /*at*/) {}
  virtual void OnDropped(const MessageCopy& /*copy*/, SimTime /*at*/, DropReason /*reason*/) {}
  virtual void OnMedium(const MediumReport& /*use*/) {}
};

class ObserverList;

// Keeps an observer subscribed to a network until destroyed or Reset (RAII).
// Move-only; must not outlive the network.
class [[nodiscard]] ObserverSubscription {
 public:
  ObserverSubscription() = default;
  ObserverSubscription(ObserverSubscription&& other) noexcept;
  ObserverSubscription& operator=(ObserverSubscription&& other) noexcept;
  ~ObserverSubscription() { Reset(); }
  void Reset();

 private:
  friend class ObserverList;
  ObserverSubscription(ObserverList* list, NetworkObserver* observer) : list_(list), observer_(observer) {}
  ObserverList* list_ = nullptr;
  NetworkObserver* observer_ = nullptr;
};

// A network's observers, in the order they subscribed (Network::Subscribe).
class ObserverList {
 public:
  ObserverSubscription Add(NetworkObserver& observer) {
    observers_.push_back(&observer);
    return ObserverSubscription(this, &observer);
  }
  bool empty() const { return observers_.empty(); }
  auto begin() const { return observers_.begin(); }
  auto end() const { return observers_.end(); }

 private:
  friend class ObserverSubscription;
  void Remove(NetworkObserver* observer);
  std::vector<NetworkObserver*> observers_;
};

}  // namespace dvpr
