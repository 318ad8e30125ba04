#pragma once
// The names a network's messages carry (network.h): LCM channels and message types interned to
// small ids once, so a message names them by id (a cheaper lookup per message); and each channel's
// members (publish/subscribe: who receives what is published on it) and whether it is link-local
// (Network::SetLinkLocal). Names handed out as string_view live as long as the table.
#include <deque>
#include <functional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "net_models/core/node_id.h"
#include "net_models/network/network_observer.h"

namespace dvpr {

class ChannelTable {
 public:
  struct Channel {
    std::string name;
    std::vector<NodeId> members;  // sorted
    bool link_local = false;
  };

  // The name's id: the one it was given, or the next.
  ChannelId InternChannel(std::string_view name);
  MessageTypeId InternType(std::string_view name);
  std::string_view ChannelName(ChannelId id) const { return channel_names_[static_cast<std::size_t>(id)]; }
  const std::string& ChannelNameString(ChannelId id) const { return channels_.at(static_cast<std::size_t>(id)).name; }
  std::string_view TypeName(MessageTypeId id) const { return type_names_[static_cast<std::size_t>(id)]; }
  // Throws std::out_of_range for an id this table did not intern.
  const Channel& At(ChannelId id) const { return channels_.at(static_cast<std::size_t>(id)); }
  // Throws std::out_of_range naming the id that this table did not intern (another network's).
  void CheckNames(ChannelId channel, MessageTypeId type) const;

  // Idempotent, as LCM's subscribe and unsubscribe.
  void Join(NodeId node, ChannelId channel);
  void Leave(NodeId node, ChannelId channel);
  void SetLinkLocal(ChannelId channel) { channels_.at(static_cast<std::size_t>(channel)).link_local = true; }

 private:
  struct StringHash {
    using is_transparent = void;
    std::size_t operator()(std::string_view s) const { return std::hash<std::string_view>{}(s); }
  };
  using NameMap = std::unordered_map<std::string, std::uint32_t, StringHash, std::equal_to<>>;

  NameMap channel_ids_;
  std::deque<Channel> channels_;                 // deque: names handed out as string_view never move
  std::vector<std::string_view> channel_names_;  // by id, into channels_: a cheaper lookup per message
  NameMap type_ids_;
  std::deque<std::string> types_;
  std::vector<std::string_view> type_names_;  // by id, into types_
};

}  // namespace dvpr
