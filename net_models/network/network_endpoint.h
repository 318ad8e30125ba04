#pragma once
// What a node of a network receives, and its receiving side (network.h; SimTransport implements
// it, agents/messages/sim_transport.h).
#include <cstdint>
#include <span>
#include <string_view>

#include "net_models/core/node_id.h"
#include "net_models/network/network_observer.h"
#include "sim/sim_time.h"

namespace dvpr {

struct ReceivedMessage {
  NodeId src;
  NodeId dst;
  ChannelId channel;
  std::string_view channel_name;
  std::span<const std::uint8_t> payload;  // valid during the OnReceive call only
  SimTime sent;
  std::uint64_t message = 0;  // the Send/SendTo call it came from (MessageCopy::message): the same for every copy
};

class NetworkEndpoint {
 public:
  virtual ~NetworkEndpoint() = default;
  virtual void OnReceive(const ReceivedMessage& message) = 0;
};

}  // namespace dvpr
