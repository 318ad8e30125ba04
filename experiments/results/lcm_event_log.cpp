#include "experiments/results/lcm_event_log.h"

#include <lcm/eventlog.h>

#include <limits>
#include <stdexcept>
#include <string>

namespace dvpr {

LcmEventLogWriter::LcmEventLogWriter(const std::filesystem::path& path)
    : path_(path), log_(lcm_eventlog_create(path.c_str(), "w")) {
  if (log_ == nullptr) throw std::runtime_error("cannot create LCM event log " + path.string());
}

LcmEventLogWriter::~LcmEventLogWriter() { Close(); }

void LcmEventLogWriter::Close() {
  if (log_ != nullptr) lcm_eventlog_destroy(log_);
  log_ = nullptr;
}

void LcmEventLogWriter::Write(std::int64_t utime, std::string_view channel, std::span<const std::uint8_t> data) {
  if (log_ == nullptr) throw std::runtime_error("LCM event log " + path_.string() + " is closed");
  if (data.size() > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max())) {
    throw std::runtime_error("LCM event log: a message of " + std::to_string(data.size()) + " bytes is too large");
  }
  // The C API takes non-const pointers but only reads through them.
  std::string channel_copy(channel);
  lcm_eventlog_event_t event{};
  event.timestamp = utime;
  event.channellen = static_cast<std::int32_t>(channel_copy.size());
  event.datalen = static_cast<std::int32_t>(data.size());
  event.channel = channel_copy.data();
  event.data = const_cast<std::uint8_t*>(data.data());
  if (lcm_eventlog_write_event(log_, &event) != 0) {
    throw std::runtime_error("cannot write to LCM event log " + path_.string());
  }
  ++events_;
}

}  // namespace dvpr
