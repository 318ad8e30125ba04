#include "agents/sim_transport.h"

#include <algorithm>

#include "sim/simulator.h"

namespace dvpr {

SimTransport::SimTransport(Network& network, NodeId node, std::int64_t start_utime)
    : network_(network), node_(node), start_utime_(start_utime) {
  network_.Attach(node_, this);
}

SimTransport::~SimTransport() {
  for (std::size_t c = 0; c < by_channel_.size(); ++c) {
    if (!by_channel_[c].handlers.empty()) network_.Leave(node_, ChannelId{static_cast<std::uint32_t>(c)});
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

std::uint64_t SimTransport::DoSubscribe(const std::string& channel, RawHandler handler) {
  const ChannelId ch = network_.InternChannel(channel);
  const auto index = static_cast<std::size_t>(ch);
  if (index >= by_channel_.size()) by_channel_.resize(index + 1);
  ChannelHandlers& entry = by_channel_[index];
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
  auto& handlers = by_channel_[static_cast<std::size_t>(ch)].handlers;
  std::erase_if(handlers, [id](const Handler& h) { return h.id == id; });
  if (handlers.empty()) network_.Leave(node_, ch);
}

void SimTransport::OnReceive(const ReceivedMessage& message) {
  const auto index = static_cast<std::size_t>(message.channel);
  if (index >= by_channel_.size()) return;
  ChannelHandlers& entry = by_channel_[index];  // deque: stays put if handlers subscribe elsewhere
  if (entry.handlers.empty()) return;
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
    (*h.fn)(entry.name, message.payload);
  }
}

}  // namespace dvpr
