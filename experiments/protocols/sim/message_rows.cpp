#include "experiments/protocols/sim/message_rows.h"

#include <string>

namespace dvpr {

void MessageRowRecorder::OnSent(const MessageCopy& copy) {
  if (rows_.empty()) first_copy_ = copy.copy;
  MessageRow& row = rows_.emplace_back();
  row.sent_ns = copy.sent.ns();
  row.src = copy.src.value;
  row.dst = copy.dst.value;
  row.channel = std::string(copy.channel_name);
  row.type = std::string(copy.type_name);
  row.payload_bytes = static_cast<std::int64_t>(copy.payload.size());
  row.wire_bytes = copy.wire_bytes;
}

void MessageRowRecorder::OnDelivered(const MessageCopy& copy, SimTime at) {
  if (MessageRow* row = RowOf(copy)) row->delivered_ns = at.ns();
}

void MessageRowRecorder::OnDropped(const MessageCopy& copy, SimTime, DropReason) {
  if (MessageRow* row = RowOf(copy)) row->dropped = true;
}

MessageRow* MessageRowRecorder::RowOf(const MessageCopy& copy) {
  if (copy.copy < first_copy_ || copy.copy - first_copy_ >= rows_.size()) return nullptr;
  return &rows_[static_cast<std::size_t>(copy.copy - first_copy_)];
}

}  // namespace dvpr
