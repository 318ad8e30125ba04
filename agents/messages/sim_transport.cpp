#include "agents/messages/sim_transport.h"

#include <algorithm>

#include "sim/simulator.h"

namespace dvpr {

SimTransport::SimTransport(Network& network, NodeId node, std::int64_t start_utime)
    : network_(network), node_(node), start_utime_(start_utime) {
  network_.Attach(node_, this);
}

SimTransport::~SimTransport() {
  for (const auto& [channel, index] : by_channel_) {
    if (!channels_[index].handlers.empty()) network_.Leave(node_, channel);
  }
  network_.Attach(node_, nullptr);
}

SimTime SimTransport::Now() const { return network_.simulator().Now(); }

void SimTransport::ScheduleAfter(SimTime delay, Callback fn) {
  network_.simulator().Schedule(delay, std::move(fn));
}

// Generated LCM types return the same static string on every call, so the
// pointer identifies the type without hashing the name.
MessageTypeId SimTransport::TypeOf(const char* type_name) {
  for (const auto& [name, id] : types_) {
    if (name == type_name) return id;
  }
  const MessageTypeId id = network_.InternType(type_name);
  types_.emplace_back(type_name, id);
  return id;
}

void SimTransport::DoPublish(const std::string& channel, const char* type_name, std::vector<std::uint8_t> bytes) {
  network_.Send(node_, network_.InternChannel(channel), TypeOf(type_name), std::move(bytes));
}

// A PublishChannel of this transport is the network's ChannelId (DoIntern).
void SimTransport::DoPublishInterned(PublishChannel channel, const char* type_name, std::vector<std::uint8_t> bytes) {
  network_.Send(node_, ChannelId{static_cast<std::uint32_t>(channel)}, TypeOf(type_name), std::move(bytes));
}

PublishChannel SimTransport::DoIntern(const std::string& name) {
  return PublishChannel{static_cast<std::uint32_t>(network_.InternChannel(name))};
}

const std::string& SimTransport::DoNameOf(PublishChannel channel) const {
  return network_.ChannelNameString(ChannelId{static_cast<std::uint32_t>(channel)});
}

SimTransport::ChannelHandlers* SimTransport::Find(ChannelId channel) {
  const auto at = std::lower_bound(by_channel_.begin(), by_channel_.end(), channel,
                                   [](const auto& e, ChannelId c) { return e.first < c; });
  if (at == by_channel_.end() || at->first != channel) return nullptr;
  return &channels_[at->second];
}

std::uint64_t SimTransport::DoSubscribe(const std::string& channel, RawHandler handler) {
  const ChannelId ch = network_.InternChannel(channel);
  ChannelHandlers* found = Find(ch);
  if (found == nullptr) {
    const auto at = std::lower_bound(by_channel_.begin(), by_channel_.end(), ch,
                                     [](const auto& e, ChannelId c) { return e.first < c; });
    by_channel_.insert(at, {ch, static_cast<std::uint32_t>(channels_.size())});
    found = &channels_.emplace_back();
    found->channel = ch;
  }
  ChannelHandlers& entry = *found;
  if (entry.handlers.empty()) {
    entry.name = channel;
    network_.Join(node_, ch);
  }
  const std::uint64_t id = next_id_++;
  entry.handlers.push_back(Handler{id, std::make_shared<RawHandler>(std::move(handler))});
  subscriptions_.emplace(id, ch);
  return id;
}

void SimTransport::DoUnsubscribe(std::uint64_t id) {
  const auto it = subscriptions_.find(id);
  if (it == subscriptions_.end()) return;
  const ChannelId ch = it->second;
  subscriptions_.erase(it);
  auto& handlers = Find(ch)->handlers;
  std::erase_if(handlers, [id](const Handler& h) { return h.id == id; });
  if (handlers.empty()) network_.Leave(node_, ch);
}

void SimTransport::OnReceive(const ReceivedMessage& message) {
  ChannelHandlers* found = Find(message.channel);
  if (found == nullptr || found->handlers.empty()) return;
  ChannelHandlers& entry = *found;  // deque: stays put if handlers subscribe elsewhere
  // Handlers may subscribe or unsubscribe while we dispatch. Ids grow in
  // subscription order, so walk by id: each step finds the next handler
  // after the one just called, and those added during dispatch are skipped.
  const std::uint64_t last_id = entry.handlers.back().id;
  std::uint64_t prev_id = 0;
  for (;;) {
    const auto it = std::upper_bound(entry.handlers.begin(), entry.handlers.end(), prev_id,
                                     [](std::uint64_t id, const Handler& h) { return id < h.id; });
    if (it == entry.handlers.end() || it->id > last_id) break;
    const Handler h = *it;  // keeps the handler alive even if it unsubscribes itself
    prev_id = h.id;
    delivery_key_ = message.message + 1;  // set per call: a handler may deliver a message of its own
    (*h.fn)(entry.name, message.payload);
  }
  delivery_key_ = 0;
}

}  // namespace dvpr
