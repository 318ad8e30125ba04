#include "experiments/results/lcm_log/lcm_event_log.h"

#include <lcm/eventlog.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>

#include "experiments/results/safe_output.h"

namespace dvpr {

// The file is an AtomicFile (safe_output.h: a private temporary, renamed into place by Close());
// LCM's writer gets a FILE over a duplicate of its descriptor. The lcm_eventlog_t is made here
// rather than by lcm_eventlog_create, which would fopen the path itself (following a link there).
LcmEventLogWriter::LcmEventLogWriter(const std::filesystem::path& path) : path_(path) {
  try {
    file_ = std::make_unique<AtomicFile>(path);
  } catch (const std::runtime_error& e) {
    throw std::runtime_error("cannot create LCM event log " + path.string() + " (" + e.what() + ")");
  }
  const int fd = ::dup(file_->fd());
  FILE* f = fd < 0 ? nullptr : ::fdopen(fd, "wb");
  if (f == nullptr) {
    if (fd >= 0) ::close(fd);
    throw std::runtime_error("cannot create LCM event log " + path.string() + " (" + std::strerror(errno) + ")");
  }
  log_ = static_cast<lcm_eventlog_t*>(std::calloc(1, sizeof(lcm_eventlog_t)));
  if (log_ == nullptr) {
    std::fclose(f);
    throw std::bad_alloc();
  }
  log_->f = f;
  log_->eventcount = 0;
}

LcmEventLogWriter::~LcmEventLogWriter() {
  try {
    Close();
  } catch (const std::exception&) {  // a failed write is reported by Close(); here it leaves no file
  }
}

void LcmEventLogWriter::Close() {
  if (log_ == nullptr) return;
  FILE* f = log_->f;
  std::free(log_);
  log_ = nullptr;
  const bool flushed = std::fflush(f) == 0 && std::ferror(f) == 0;
  const int saved = errno;
  const bool closed = std::fclose(f) == 0;
  if (!flushed || !closed) {
    throw std::runtime_error("cannot write to LCM event log " + path_.string() + " (" +
                             std::strerror(flushed ? errno : saved) + ")");
  }
  file_->Commit();
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
