#include "net_models/network/network.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

#include "sim/simulator.h"

namespace dvpr {

namespace {

NetworkStack WithAccess(std::unique_ptr<LinkModel> link) {
  NetworkStack stack;
  stack.access = std::move(link);
  return stack;
}

}  // namespace

Network::Network(Simulator& sim, int nodes, std::unique_ptr<LinkModel> link, WireParams wire)
    : Network(sim, nodes, WithAccess(std::move(link)), wire) {}

Network::Network(Simulator& sim, int nodes, NetworkStack stack, WireParams wire)
    : sim_(sim),
      nodes_(nodes),
      stack_(NetworkStack::Completed(std::move(stack), nodes)),
      channel_(*stack_.propagation, stack_.loss.get()),
      wire_(wire),
      availability_(nodes),
      forwarder_(sim, nodes, stack_, availability_, *this),
      pairs_(std::max(nodes, 1)) {
  stack_.disconnected.Validate();
  forwarder_.Bind(channel_);
  wire_.Validate();
  endpoints_.assign(static_cast<std::size_t>(nodes), nullptr);
  senders_.assign(static_cast<std::size_t>(nodes), NodeCounters{});
}

Network::~Network() = default;

void Network::CheckNode(NodeId node, const char* what) const {
  if (node.value < 0 || node.value >= nodes_) {
    throw std::out_of_range(std::string("Network::") + what + ": node " + std::to_string(node.value) +
                            " outside [0, " + std::to_string(nodes_) + ")");
  }
}

void Network::Attach(NodeId node, NetworkEndpoint* endpoint) {
  CheckNode(node, "Attach");
  endpoints_[static_cast<std::size_t>(node.value)] = endpoint;
}

void Network::Join(NodeId node, ChannelId channel) {
  CheckNode(node, "Join");
  names_.Join(node, channel);
}

void Network::SetOffline(NodeId node, SimTime from, SimTime until) {
  CheckNode(node, "SetOffline");
  availability_.SetOffline(node, from, until);
}

void Network::SetTalkWindows(NodeId node, std::vector<TalkWindow> windows) {
  CheckNode(node, "SetTalkWindows");
  availability_.SetTalkWindows(node, std::move(windows));
}

std::size_t Network::Send(NodeId src, ChannelId channel, MessageTypeId type, std::vector<std::uint8_t> payload) {
  CheckNode(src, "Send");
  dsts_.clear();
  const ChannelTable::Channel& ch = names_.At(channel);
  for (const NodeId member : ch.members) {
    if (member != src) dsts_.push_back(member);
  }
  if (ch.link_local) channel_.KeepHearers(src, dsts_, sim_.Now());
  Dispatch(src, channel, type, std::move(payload));
  return dsts_.size();
}

void Network::SendTo(NodeId src, std::span<const NodeId> dsts, ChannelId channel, MessageTypeId type,
                     std::vector<std::uint8_t> payload) {
  CheckNode(src, "SendTo");
  dsts_.assign(dsts.begin(), dsts.end());
  for (const NodeId dst : dsts_) {
    CheckNode(dst, "SendTo");
    if (dst == src) throw std::invalid_argument("Network::SendTo: a node does not send to itself");
  }
  Dispatch(src, channel, type, std::move(payload));
}

// The forwarder transmits to every destination in dsts_ at once (a shared medium needs them
// together) and takes each copy on its way; the message's payload is one slot they all share.
void Network::Dispatch(NodeId src, ChannelId channel, MessageTypeId type, std::vector<std::uint8_t>&& payload) {
  names_.CheckNames(channel, type);
  const SimTime now = sim_.Now();
  NodeCounters& sender = senders_[static_cast<std::size_t>(src.value)];
  ++sender.published;
  const std::uint64_t message = messages_++;
  if (dsts_.empty()) return;

  frames_.clear();
  const auto payload_bytes = static_cast<std::int64_t>(payload.size());
  const WireFootprint fp = AppendLinkFrames(
      Bytes(payload_bytes), static_cast<std::int64_t>(ChannelName(channel).size()), wire_, frames_);
  const bool link_local = names_.At(channel).link_local;
  const LinkModel::MediumUse use = forwarder_.Transmit(src, dsts_, frames_, /*routed=*/!link_local);
  sender.transmissions += use.transmissions;
  sender.medium_bytes += use.bytes.value();
  if (link_local) {
    sender.routing_transmissions += use.transmissions;
    sender.routing_bytes += use.bytes.value();
  }

  const std::uint32_t slot = payloads_.Acquire(Payload{.bytes = std::move(payload), .message = message, .sent = now,
                                                       .wire_bytes = fp.wire_bytes.value(), .refs = 0, .src = src,
                                                       .channel = channel, .type = type});
  forwarder_.Open(slot);
  Payload& p = payloads_[slot];
  for (std::size_t i = 0; i < dsts_.size(); ++i) {
    const NodeId dst = dsts_[i];
    const std::uint64_t copy = copies_++;
    LinkCounters& c = pairs_.At(src, dst);
    ++c.messages;
    c.payload_bytes += payload_bytes;
    c.wire_bytes += p.wire_bytes;
    const DropReason drop = forwarder_.Take(slot, i, src, dst, copy);
    if (!observers_.empty()) NotifySent(p, dst, copy, drop);
    if (drop != DropReason::kNone) {
      ++c.dropped;
      CountDrop(drop);
      continue;
    }
    ++p.refs;
  }
  if (!observers_.empty()) NotifyMedium(p, src, use);
  if (p.refs == 0) {
    Release(slot);
    return;
  }
  forwarder_.Launch(slot);
}

void Network::DropCopy(std::uint32_t slot, const PendingCopy& c, DropReason reason) {
  const Payload& p = payloads_[slot];
  ++pairs_.At(p.src, c.dst).dropped;
  CountDrop(reason);
  if (!observers_.empty()) {
    const MessageCopy m = CopyOf(p, c.dst, c.copy, static_cast<int>(c.hops));
    for (NetworkObserver* o : observers_) o->OnDropped(m, sim_.Now(), reason);
  }
}

void Network::AppendFrames(std::uint32_t slot, std::vector<Bytes>& frames) const {
  const Payload& p = payloads_[slot];
  AppendLinkFrames(Bytes(static_cast<std::int64_t>(p.bytes.size())),
                   static_cast<std::int64_t>(ChannelName(p.channel).size()), wire_, frames);
}

void Network::SentOn(std::uint32_t slot, NodeId sender, const LinkModel::MediumUse& use) {
  const Payload& p = payloads_[slot];
  NodeCounters& counters = senders_[static_cast<std::size_t>(sender.value)];
  counters.transmissions += use.transmissions;
  counters.medium_bytes += use.bytes.value();
  if (sender != p.src) {  // (a sender that held its own message sends it now: not a relay)
    counters.relay_transmissions += use.transmissions;
    counters.relay_bytes += use.bytes.value();
  }
  // (a retry that finds no route yet sends nothing, and reports nothing)
  if (!observers_.empty() && use.transmissions > 0) NotifyMedium(p, sender, use);
}

void Network::NotifyMedium(const Payload& p, NodeId sender, const LinkModel::MediumUse& use) {
  const MediumReport m{.message = p.message,
                       .sent = p.sent,
                       .src = sender,
                       .channel = p.channel,
                       .channel_name = ChannelName(p.channel),
                       .transmissions = use.transmissions,
                       .bytes = use.bytes.value()};
  for (NetworkObserver* o : observers_) o->OnMedium(m);
}

MessageCopy Network::CopyOf(const Payload& p, NodeId dst, std::uint64_t copy, int hops) const {
  return MessageCopy{.message = p.message,
                     .copy = copy,
                     .sent = p.sent,
                     .src = p.src,
                     .dst = dst,
                     .channel = p.channel,
                     .channel_name = ChannelName(p.channel),
                     .type = p.type,
                     .type_name = TypeName(p.type),
                     .payload = p.bytes,
                     .wire_bytes = p.wire_bytes,
                     .hops = hops};
}

void Network::NotifySent(const Payload& p, NodeId dst, std::uint64_t copy, DropReason drop) {
  const MessageCopy m = CopyOf(p, dst, copy, 0);
  for (NetworkObserver* o : observers_) o->OnSent(m);
  if (drop == DropReason::kNone) return;
  for (NetworkObserver* o : observers_) o->OnDropped(m, p.sent, drop);
}

void Network::Deliver(std::uint32_t slot, const PendingCopy& copy) {
  const SimTime now = sim_.Now();
  const NodeId dst = copy.dst;
  const auto hops = static_cast<int>(copy.hops);
  Payload& p = payloads_[slot];
  LinkCounters& c = pairs_.At(p.src, dst);
  const bool online = IsOnline(dst, now);
  ++(online ? c.delivered : c.dropped);
  if (online) {
    ++routes_.delivered;
    routes_.delivered_hops += copy.hops;
    routes_.max_hops = std::max(routes_.max_hops, hops);
  } else {
    CountDrop(DropReason::kOffline);
  }
  if (!observers_.empty()) {
    const MessageCopy m = CopyOf(p, dst, copy.copy, hops);
    for (NetworkObserver* o : observers_) {
      if (online) {
        o->OnDelivered(m, now);
      } else {
        o->OnDropped(m, now, DropReason::kOffline);
      }
    }
  }
  if (!online) {
    Release(slot);
    return;
  }
  // OnReceive may send (and grow payloads_), so copy what it needs first; the
  // byte buffer itself does not move while this delivery holds a reference.
  const ReceivedMessage m{p.src, dst, p.channel, ChannelName(p.channel), p.bytes, p.sent, p.message};
  if (NetworkEndpoint* endpoint = endpoints_[static_cast<std::size_t>(dst.value)]) endpoint->OnReceive(m);
  Release(slot);
}

LinkCounters Network::Totals() const {
  LinkCounters t;
  pairs_.ForEach([&t](const LinkCounters& c) {
    t.messages += c.messages;
    t.payload_bytes += c.payload_bytes;
    t.wire_bytes += c.wire_bytes;
    t.delivered += c.delivered;
    t.dropped += c.dropped;
  });
  return t;
}

const LinkCounters& Network::Counters(NodeId src, NodeId dst) const {
  static const LinkCounters kNone;
  const LinkCounters* c = pairs_.Find(src, dst);
  return c != nullptr ? *c : kNone;
}

}  // namespace dvpr
