#include "experiments/protocols/sim/message_rows.h"

#include "lcmtypes/channels/channels.h"

namespace dvpr {

void MessageRowRecorder::OnSent(const MessageCopy& copy) {
  if (records_.empty()) first_copy_ = copy.copy;
  Remember(channel_names_, static_cast<std::uint32_t>(copy.channel), copy.channel_name);
  Remember(type_names_, static_cast<std::uint32_t>(copy.type), copy.type_name);
  records_.push_back(Record{.sent_ns = copy.sent.ns(),
                            .payload_bytes = static_cast<std::int64_t>(copy.payload.size()),
                            .wire_bytes = copy.wire_bytes,
                            .src = copy.src,
                            .dst = copy.dst,
                            .channel = copy.channel,
                            .type = copy.type});
}

void MessageRowRecorder::OnDelivered(const MessageCopy& copy, SimTime at) {
  if (Record* r = RecordOf(copy)) {
    r->delivered_ns = at.ns();
    r->hops = copy.hops;
  }
}

void MessageRowRecorder::OnDropped(const MessageCopy& copy, SimTime, DropReason) {
  if (Record* r = RecordOf(copy)) {
    r->dropped = true;
    r->hops = copy.hops;
  }
}

MessageRowRecorder::Record* MessageRowRecorder::RecordOf(const MessageCopy& copy) {
  if (copy.copy < first_copy_ || copy.copy - first_copy_ >= records_.size()) return nullptr;
  return &records_[static_cast<std::size_t>(copy.copy - first_copy_)];
}

void MessageRowRecorder::Learn(std::vector<std::string>& names, std::uint32_t id, std::string_view name) {
  if (id >= names.size()) names.resize(id + 1);
  names[id] = std::string(name);
}

std::vector<MessageRow> MessageRowRecorder::Rows() const {
  std::vector<MessageRow> rows;
  rows.reserve(records_.size());
  for (const Record& r : records_) {
    MessageRow& row = rows.emplace_back();
    row.sent_ns = r.sent_ns;
    if (r.delivered_ns >= 0) row.delivered_ns = r.delivered_ns;
    row.src = r.src.value;
    row.dst = r.dst.value;
    row.channel = channel_names_[static_cast<std::size_t>(r.channel)];
    row.type = type_names_[static_cast<std::size_t>(r.type)];
    row.payload_bytes = r.payload_bytes;
    row.wire_bytes = r.wire_bytes;
    row.dropped = r.dropped;
    row.hops = r.hops;
    row.role = kMessageRoleNames[static_cast<std::size_t>(channels::RoleOf(row.channel))];
  }
  return rows;
}

}  // namespace dvpr
