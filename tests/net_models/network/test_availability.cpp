// When a node can talk (net_models/network/availability.h), at the edges of its intervals, worked by hand:
// an interval [from, until) holds `from` and not `until`.
#include "net_models/network/availability.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace dvpr {
namespace {

SimTime S(std::int64_t s) { return SimTime::Millis(s * 1000); }

TEST(Availability, ANodeIsOnlineUntilToldOtherwise) {
  const Availability a(3);
  for (int n = 0; n < 3; ++n) EXPECT_TRUE(a.IsOnline(NodeId(n), S(1'000'000)));
}

TEST(Availability, OfflineHoldsItsStartAndNotItsEnd) {
  Availability a(2);
  a.SetOffline(NodeId(1), S(10), S(20));
  EXPECT_TRUE(a.IsOnline(NodeId(1), S(10) - SimTime::Nanos(1)));
  EXPECT_FALSE(a.IsOnline(NodeId(1), S(10)));
  EXPECT_TRUE(a.DroppedOut(NodeId(1), S(20) - SimTime::Nanos(1)));
  EXPECT_TRUE(a.IsOnline(NodeId(1), S(20)));
  EXPECT_TRUE(a.IsOnline(NodeId(0), S(15)));  // the other node is untouched
}

TEST(Availability, TalkWindowsHoldTheirStartsAndNotTheirEnds) {
  Availability a(2);
  a.SetTalkWindows(NodeId(0), {TalkWindow{S(0), S(5)}, TalkWindow{S(10), S(15)}});
  EXPECT_TRUE(a.InTalkWindow(NodeId(0), S(0)));
  EXPECT_FALSE(a.InTalkWindow(NodeId(0), S(5)));
  EXPECT_FALSE(a.InTalkWindow(NodeId(0), S(7)));
  EXPECT_TRUE(a.InTalkWindow(NodeId(0), S(10)));
  EXPECT_FALSE(a.InTalkWindow(NodeId(0), S(15)));
  EXPECT_FALSE(a.IsOnline(NodeId(0), S(100)));
  EXPECT_FALSE(a.DroppedOut(NodeId(0), S(100)));  // silent, not dropped out
  EXPECT_TRUE(a.IsOnline(NodeId(1), S(7)));        // no windows: always talks
}

TEST(Availability, OverlappingOrEmptyWindowsAreRefusedByIndex) {
  Availability a(1);
  try {
    a.SetTalkWindows(NodeId(0), {TalkWindow{S(0), S(5)}, TalkWindow{S(4), S(8)}});
    FAIL() << "overlapping windows were accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()),
              "Network::SetTalkWindows: node 0: window 1 is empty or not after the one before it");
  }
  EXPECT_THROW(a.SetTalkWindows(NodeId(0), {TalkWindow{S(3), S(3)}}), std::invalid_argument);
}

}  // namespace
}  // namespace dvpr
