// The LCM event-log writer: what it writes reads back through LCM's own
// lcm/eventlog.h, event by event, with the caller's timestamps.
#include <gtest/gtest.h>
#include <lcm/eventlog.h>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "experiments/results/lcm_log/lcm_event_log.h"

namespace dvpr {
namespace {

namespace fs = std::filesystem;

struct Event {
  std::int64_t eventnum;
  std::int64_t utime;
  std::string channel;
  std::vector<std::uint8_t> data;
  bool operator==(const Event&) const = default;
};

std::vector<Event> ReadBack(const fs::path& path) {
  std::vector<Event> events;
  lcm_eventlog_t* log = lcm_eventlog_create(path.c_str(), "r");
  if (log == nullptr) throw std::runtime_error("cannot open " + path.string());
  while (lcm_eventlog_event_t* e = lcm_eventlog_read_next_event(log)) {
    const auto* bytes = static_cast<const std::uint8_t*>(e->data);
    events.push_back(Event{e->eventnum, e->timestamp, std::string(e->channel, static_cast<std::size_t>(e->channellen)),
                           std::vector<std::uint8_t>(bytes, bytes + e->datalen)});
    lcm_eventlog_free_event(e);
  }
  lcm_eventlog_destroy(log);
  return events;
}

TEST(LcmEventLogWriter, EventsReadBackInOrderWithTheirTimestamps) {
  const fs::path path = fs::path(DVPR_TEST_TMP) / "writer.lcmlog";
  fs::create_directories(path.parent_path());
  const std::vector<std::uint8_t> a{1, 2, 3};
  const std::vector<std::uint8_t> b{};
  {
    LcmEventLogWriter writer(path);
    writer.Write(9712, "DVPR_QUERY_ALL", a);
    writer.Write(15400, "DVPR_MATCH_0", b);
    EXPECT_EQ(writer.EventsWritten(), 2);
    writer.Close();
    EXPECT_THROW(writer.Write(0, "X", a), std::runtime_error);
  }
  EXPECT_EQ(ReadBack(path), (std::vector<Event>{{0, 9712, "DVPR_QUERY_ALL", a}, {1, 15400, "DVPR_MATCH_0", b}}));
}

TEST(LcmEventLogWriter, UnwritablePathIsAnErrorNamingIt) {
  const fs::path path = fs::path(DVPR_TEST_TMP) / "no_such_dir" / "x.lcmlog";
  try {
    LcmEventLogWriter writer(path);
    ADD_FAILURE() << "created " << path;
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace dvpr
