#pragma once
// network.schedule (issue 35, item 3): the windows in which each robot can talk, in Swarm-SLAM's
// connectivity-schedule form - a CSV file with a header naming robot, start_s and end_s (or
// ROBOT_ID, START_S, END_S, any case) and one window a line. A robot the file does not name
// talks all the time; one it names talks only inside its windows (Network::SetTalkWindows).
#include <filesystem>
#include <vector>

#include "net_models/network/network.h"

namespace dvpr {

struct ScheduledWindow {
  int robot = 0;
  TalkWindow window;
  bool operator==(const ScheduledWindow&) const = default;
};

// The file's windows, by robot and then start. Throws std::invalid_argument naming the file, the
// line and what was expected: a path that is not a regular file (a folder, a FIFO, a device, a
// loop of symbolic links; found by stat, never opened), no header or a header without one of the
// three columns or naming one twice (robot and ROBOT_ID), a robot that is not an integer in
// [0, 32767] or is above `largest_robot` (in no team of the sweep), a time that is not a finite
// number of seconds in [0, 360 000 000] (100 000 h, the dropout's limit), a window whose end is
// not after its start, two windows of one robot that overlap (both lines named), or a file without
// a window. A UTF-8 byte-order mark before the header is skipped; quoted file text is printable
// (printable.h).
std::vector<ScheduledWindow> ReadTalkSchedule(const std::filesystem::path& path, int largest_robot = 32767);

}  // namespace dvpr
