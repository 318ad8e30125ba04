#pragma once
// LCM event logs (the format of lcm-logger, read by lcm-logplayer, lcm-spy
// and every LCM binding), written through LCM's own lcm/eventlog.h. The writer
// knows the file format only: the caller stamps each event (dvpr's simulation
// stamps virtual time in microseconds since its start, see
// protocols/sim/event_log_recorder.h; lcm-logplayer replays the gaps between
// timestamps, not their absolute values).
#include <cstdint>
#include <filesystem>
#include <span>
#include <string_view>

struct _lcm_eventlog_t;

namespace dvpr {

class LcmEventLogWriter {
 public:
  // Creates (truncates) the file; throws std::runtime_error naming the path on failure.
  explicit LcmEventLogWriter(const std::filesystem::path& path);
  ~LcmEventLogWriter();
  LcmEventLogWriter(const LcmEventLogWriter&) = delete;
  LcmEventLogWriter& operator=(const LcmEventLogWriter&) = delete;

  // Appends one event stamped `utime` (microseconds); throws std::runtime_error if the write fails.
  void Write(std::int64_t utime, std::string_view channel, std::span<const std::uint8_t> data);
  // Flushes and closes the file (the destructor does this too).
  void Close();
  std::int64_t EventsWritten() const { return events_; }

 private:
  std::filesystem::path path_;
  _lcm_eventlog_t* log_ = nullptr;
  std::int64_t events_ = 0;
};

}  // namespace dvpr
