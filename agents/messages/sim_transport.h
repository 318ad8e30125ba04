#pragma once
// The Transport of one robot in simulation: virtual time from the Simulator,
// timers as simulator events, messages through the simulated Network. Robot
// r is network node r. Publishing hands the encoded bytes to the Network
// (moved, not copied); a delivery calls every handler this robot subscribed
// on the message's channel, in subscription order. Each delivery is named by the
// network's message number, so the transports of a run that share one
// DecodedMessages (ShareDecodes) decode a broadcast once for all its receivers.
#include <cstdint>
#include <deque>
#include <memory>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "agents/algorithms/ids.h"
#include "agents/messages/transport.h"
#include "net_models/network/network.h"

namespace dvpr {

class SimTransport final : public Transport, private NetworkEndpoint {
 public:
  // Attaches to `network` as `node` (one transport per node). start_utime: virtual time 0 as
  // microseconds since the Unix epoch (the config's start_time), for the messages' utime.
  SimTransport(Network& network, NodeId node, std::int64_t start_utime = 0);
  ~SimTransport() override;
  SimTransport(const SimTransport&) = delete;
  SimTransport& operator=(const SimTransport&) = delete;

  NodeId node() const { return node_; }
  RobotId robot() const { return RobotId(node_.value); }

  SimTime Now() const override;
  std::int64_t UtimeAt(SimTime t) const override { return start_utime_ + t.us(); }
  void ScheduleAfter(SimTime delay, Callback fn) override;

 private:
  struct Handler {
    std::uint64_t id;
    std::shared_ptr<RawHandler> fn;  // shared: a handler may unsubscribe itself while running
  };
  struct ChannelHandlers {
    ChannelId channel{};
    std::string name;
    std::vector<Handler> handlers;
  };

  void DoPublish(const std::string& channel, const char* type_name, std::vector<std::uint8_t> bytes) override;
  void DoPublishInterned(PublishChannel channel, const char* type_name, std::vector<std::uint8_t> bytes) override;
  PublishChannel DoIntern(const std::string& name) override;
  const std::string& DoNameOf(PublishChannel channel) const override;
  std::uint64_t DoSubscribe(const std::string& channel, RawHandler handler) override;
  void DoUnsubscribe(std::uint64_t id) override;
  void OnReceive(const ReceivedMessage& message) override;
  MessageTypeId TypeOf(const char* type_name);
  // The channel's entry; null if this robot never subscribed to it.
  ChannelHandlers* Find(ChannelId channel);

  Network& network_;
  NodeId node_;
  std::int64_t start_utime_;
  // The channels this robot subscribed to (a handful), not a slot per channel id of the network:
  // 1000 robots intern thousands of channels. Deque: entries stay put while handlers subscribe.
  std::deque<ChannelHandlers> channels_;
  std::vector<std::pair<ChannelId, std::uint32_t>> by_channel_;  // sorted: channel -> channels_ index
  std::unordered_map<std::uint64_t, ChannelId> subscriptions_;  // id -> channel
  std::vector<std::pair<const char*, MessageTypeId>> types_;  // getTypeName() pointers seen
  std::uint64_t next_id_ = 1;
};

}  // namespace dvpr
