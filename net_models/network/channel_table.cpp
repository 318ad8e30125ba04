#include "net_models/network/channel_table.h"

#include <algorithm>
#include <stdexcept>

namespace dvpr {

// Ids come from this table's Intern calls; another network's ids would name nothing here.
void ChannelTable::CheckNames(ChannelId channel, MessageTypeId type) const {
  if (static_cast<std::size_t>(channel) >= channel_names_.size()) {
    throw std::out_of_range("Network: channel id " + std::to_string(static_cast<std::uint32_t>(channel)) +
                            " was not interned by this network");
  }
  if (static_cast<std::size_t>(type) >= type_names_.size()) {
    throw std::out_of_range("Network: message type id " + std::to_string(static_cast<std::uint32_t>(type)) +
                            " was not interned by this network");
  }
}

ChannelId ChannelTable::InternChannel(std::string_view name) {
  if (auto it = channel_ids_.find(name); it != channel_ids_.end()) return ChannelId{it->second};
  const auto id = static_cast<std::uint32_t>(channels_.size());
  channels_.push_back(Channel{std::string(name), {}});
  channel_names_.push_back(channels_.back().name);
  channel_ids_.emplace(std::string(name), id);
  return ChannelId{id};
}

MessageTypeId ChannelTable::InternType(std::string_view name) {
  if (auto it = type_ids_.find(name); it != type_ids_.end()) return MessageTypeId{it->second};
  const auto id = static_cast<std::uint32_t>(types_.size());
  types_.emplace_back(name);
  type_names_.push_back(types_.back());
  type_ids_.emplace(std::string(name), id);
  return MessageTypeId{id};
}

void ChannelTable::Join(NodeId node, ChannelId channel) {
  auto& members = channels_.at(static_cast<std::size_t>(channel)).members;
  const auto it = std::lower_bound(members.begin(), members.end(), node);
  if (it == members.end() || *it != node) members.insert(it, node);
}

void ChannelTable::Leave(NodeId node, ChannelId channel) {
  auto& members = channels_.at(static_cast<std::size_t>(channel)).members;
  const auto it = std::lower_bound(members.begin(), members.end(), node);
  if (it != members.end() && *it == node) members.erase(it);
}

}  // namespace dvpr
