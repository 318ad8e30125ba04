#pragma once
// LCM event logs (the format of lcm-logger, read by lcm-logplayer, lcm-spy
// and every LCM binding), written through LCM's own lcm/eventlog.h. The writer
// knows the file format only: the caller stamps each event (dvpr's simulation
// stamps virtual time in microseconds since its start, see
// protocols/sim/event_log_recorder.h; lcm-logplayer replays the gaps between
// timestamps, not their absolute values).
#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <string_view>

struct _lcm_eventlog_t;

namespace dvpr {

class AtomicFile;

class LcmEventLogWriter {
 public:
  // Starts the file as a private temporary beside `path` (safe_output.h); throws
  // std::runtime_error naming the path on failure.
  explicit LcmEventLogWriter(const std::filesystem::path& path);
  ~LcmEventLogWriter();
  LcmEventLogWriter(const LcmEventLogWriter&) = delete;
  LcmEventLogWriter& operator=(const LcmEventLogWriter&) = delete;

  // Appends one event stamped `utime` (microseconds); throws std::runtime_error if the write fails.
  void Write(std::int64_t utime, std::string_view channel, std::span<const std::uint8_t> data);
  // Flushes and closes the file, checked, and puts it in place at the path; throws
  // std::runtime_error naming it if a write failed (then no file is left). The destructor
  // does this too, without the error.
  void Close();
  std::int64_t EventsWritten() const { return events_; }

 private:
  std::filesystem::path path_;
  std::unique_ptr<AtomicFile> file_;
  _lcm_eventlog_t* log_ = nullptr;
  std::int64_t events_ = 0;
};

}  // namespace dvpr
