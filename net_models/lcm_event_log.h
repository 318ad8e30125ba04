#pragma once
// LCM event logs (the format of lcm-logger, read by lcm-logplayer, lcm-spy
// and every LCM binding), written through LCM's own lcm/eventlog.h. Event
// timestamps are virtual time in microseconds since the simulation start
// (SimTime::us(), truncating), plus an optional offset: lcm-logplayer replays
// the gaps between timestamps, not their absolute values.
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "sim/sim_time.h"

struct _lcm_eventlog_t;

namespace dvpr {

class LcmEventLogWriter {
 public:
  // Creates (truncates) the file; throws std::runtime_error naming the path on failure.
  explicit LcmEventLogWriter(const std::filesystem::path& path, std::int64_t utime_offset = 0);
  ~LcmEventLogWriter();
  LcmEventLogWriter(const LcmEventLogWriter&) = delete;
  LcmEventLogWriter& operator=(const LcmEventLogWriter&) = delete;

  // Appends one event; throws std::runtime_error if the write fails.
  void Write(SimTime time, std::string_view channel, std::span<const std::uint8_t> data);
  // Flushes and closes the file (the destructor does this too).
  void Close();
  std::int64_t EventsWritten() const { return events_; }

 private:
  std::filesystem::path path_;
  std::int64_t utime_offset_;
  _lcm_eventlog_t* log_ = nullptr;
  std::int64_t events_ = 0;
};

// One event read back from a log.
struct LcmLogEvent {
  std::int64_t eventnum = 0;
  std::int64_t utime = 0;
  std::string channel;
  std::vector<std::uint8_t> data;
};

// Reads every event of an LCM log through lcm/eventlog.h (for tests and
// tools); throws std::runtime_error naming the path if it cannot be opened.
std::vector<LcmLogEvent> ReadLcmEventLog(const std::filesystem::path& path);

}  // namespace dvpr
