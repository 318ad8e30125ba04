#include "net_models/lcm_event_log.h"

#include <lcm/eventlog.h>

#include <limits>
#include <stdexcept>

namespace dvpr {

LcmEventLogWriter::LcmEventLogWriter(const std::filesystem::path& path, std::int64_t utime_offset)
    : path_(path), utime_offset_(utime_offset), log_(lcm_eventlog_create(path.c_str(), "w")) {
  if (log_ == nullptr) throw std::runtime_error("cannot create LCM event log " + path.string());
}

LcmEventLogWriter::~LcmEventLogWriter() { Close(); }

void LcmEventLogWriter::Close() {
  if (log_ != nullptr) lcm_eventlog_destroy(log_);
  log_ = nullptr;
}

void LcmEventLogWriter::Write(SimTime time, std::string_view channel, std::span<const std::uint8_t> data) {
  if (log_ == nullptr) throw std::runtime_error("LCM event log " + path_.string() + " is closed");
  if (data.size() > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max())) {
    throw std::runtime_error("LCM event log: a message of " + std::to_string(data.size()) + " bytes is too large");
  }
  // The C API takes non-const pointers but only reads through them.
  std::string channel_copy(channel);
  lcm_eventlog_event_t event{};
  event.timestamp = time.us() + utime_offset_;
  event.channellen = static_cast<std::int32_t>(channel_copy.size());
  event.datalen = static_cast<std::int32_t>(data.size());
  event.channel = channel_copy.data();
  event.data = const_cast<std::uint8_t*>(data.data());
  if (lcm_eventlog_write_event(log_, &event) != 0) {
    throw std::runtime_error("cannot write to LCM event log " + path_.string());
  }
  ++events_;
}

std::vector<LcmLogEvent> ReadLcmEventLog(const std::filesystem::path& path) {
  lcm_eventlog_t* log = lcm_eventlog_create(path.c_str(), "r");
  if (log == nullptr) throw std::runtime_error("cannot open LCM event log " + path.string());
  std::vector<LcmLogEvent> events;
  while (lcm_eventlog_event_t* e = lcm_eventlog_read_next_event(log)) {
    const auto* bytes = static_cast<const std::uint8_t*>(e->data);
    events.push_back(LcmLogEvent{e->eventnum, e->timestamp, std::string(e->channel, e->channellen),
                                 std::vector<std::uint8_t>(bytes, bytes + e->datalen)});
    lcm_eventlog_free_event(e);
  }
  lcm_eventlog_destroy(log);
  return events;
}

}  // namespace dvpr
