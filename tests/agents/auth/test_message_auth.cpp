// The team's message tags (agents/auth/message_auth.h): the trailer's layout and its tag against
// Python's hmac module, every kind of tampering refused, and the replay window worked by hand.
#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "agents/auth/message_auth.h"

namespace dvpr::auth {
namespace {

Secret Counting() {
  Secret s{};
  for (std::size_t i = 0; i < s.size(); ++i) s[i] = static_cast<std::uint8_t>(i);
  return s;
}

std::vector<std::uint8_t> Bytes(const std::string& text) { return {text.begin(), text.end()}; }

std::string Hex(const std::uint8_t* p, std::size_t n) {
  static constexpr char kDigits[] = "0123456789abcdef";
  std::string s;
  for (std::size_t i = 0; i < n; ++i) {
    s.push_back(kDigits[p[i] >> 4]);
    s.push_back(kDigits[p[i] & 15]);
  }
  return s;
}

// The trailer of the 7th message of robot 3 (instance 0x123456789abc) on DVPR_QUERY_1 with the
// message "hello" and the secret 00 01 .. 1f. Its tag, from Python's hmac module:
//   key = bytes(range(32))
//   fields = (3).to_bytes(2,'big') + (0x123456789abc).to_bytes(8,'big') + (7).to_bytes(8,'big')
//   hmac.new(key, b'dvpr-tag-1\0' + b'DVPR_QUERY_1' + b'\0' + b'hello' + fields,
//            hashlib.sha256).hexdigest()[:32]   ->   227cce91b9ada49c11c5f59988c491be
TEST(MessageAuth, TheTrailerIsTheDocumentedFieldsAndTheTruncatedHmacOfPython) {
  MessageAuth a(Counting(), 3, 0x123456789abc);
  std::vector<std::uint8_t> m;
  for (int i = 0; i < 7; ++i) {
    m = Bytes("hello");
    a.Seal("DVPR_QUERY_1", m);
  }
  ASSERT_EQ(m.size(), 5 + kTrailerBytes);
  EXPECT_EQ(kTrailerBytes, 34u);
  EXPECT_EQ(std::string(m.begin(), m.begin() + 5), "hello");
  EXPECT_EQ(Hex(m.data() + 5, 18), "00030000123456789abc0000000000000007");
  EXPECT_EQ(Hex(m.data() + 23, 16), "227cce91b9ada49c11c5f59988c491be");

  const std::optional<Opened> o = MessageAuth(Counting(), -1).Open("DVPR_QUERY_1", m);
  ASSERT_TRUE(o.has_value());
  EXPECT_EQ(std::string(o->message.begin(), o->message.end()), "hello");
  EXPECT_EQ(o->origin.robot, 3);
  EXPECT_EQ(o->origin.instance, 0x123456789abcu);
  EXPECT_EQ(o->origin.counter, 7u);
  EXPECT_EQ(RobotOfSender(o->origin.SenderKey()), 3);
}

TEST(MessageAuth, AnyChangedByteAnotherChannelOrSecretOrATruncationIsRefused) {
  MessageAuth a(Counting(), 1);
  const MessageAuth reader(Counting(), -1);
  std::vector<std::uint8_t> m = Bytes("a query of some length");
  a.Seal("DVPR_QUERY_0", m);
  ASSERT_TRUE(reader.Open("DVPR_QUERY_0", m).has_value());
  for (std::size_t i = 0; i < m.size(); ++i) {
    std::vector<std::uint8_t> changed = m;
    changed[i] ^= 0x01;  // the message, the robot (relabelling), the instance, the counter, the tag
    EXPECT_FALSE(reader.Open("DVPR_QUERY_0", changed).has_value()) << "byte " << i;
  }
  EXPECT_FALSE(reader.Open("DVPR_QUERY_2", m).has_value());  // moved to another robot's channel
  Secret other = Counting();
  other[31] ^= 0x80;
  EXPECT_FALSE(MessageAuth(other, -1).Open("DVPR_QUERY_0", m).has_value());
  for (std::size_t n : {std::size_t{0}, std::size_t{1}, kTrailerBytes - 1, kTrailerBytes, m.size() - 1}) {
    EXPECT_FALSE(reader.Open("DVPR_QUERY_0", std::span<const std::uint8_t>(m.data(), n)).has_value()) << n;
  }
  // An empty message seals and opens too (34 bytes of trailer alone).
  std::vector<std::uint8_t> empty;
  a.Seal("DVPR_STATUS", empty);
  const auto o = reader.Open("DVPR_STATUS", empty);
  ASSERT_TRUE(o.has_value());
  EXPECT_TRUE(o->message.empty());
  EXPECT_EQ(o->origin.counter, 2u);
}

TEST(MessageAuth, AListenerCannotSealAndRobotsOutsideTheWireAreRefused) {
  MessageAuth listener(Counting(), -1);
  std::vector<std::uint8_t> m = Bytes("x");
  EXPECT_THROW(listener.Seal("C", m), std::logic_error);
  EXPECT_THROW(MessageAuth(Counting(), 32768), std::invalid_argument);
  EXPECT_THROW(MessageAuth(Counting(), -2), std::invalid_argument);
  EXPECT_NE(MessageAuth(Counting(), 0).instance(), 0u);  // drawn
}

TEST(MessageAuth, SocketKeysAreNoRobotsSenderKeys) {
  // A socket's key (udpm::Sender::Key(): (address << 16 | port) + 1) stays below 2^48.
  const std::uint64_t largest_socket = ((std::uint64_t{0xFFFFFFFF} << 16) | 0xFFFF) + 1;
  EXPECT_EQ(RobotOfSender(largest_socket - 1), -1);
  EXPECT_EQ(RobotOfSender(0), -1);
  EXPECT_EQ(RobotOfSender(Origin{0, 1, 1}.SenderKey()), 0);
  EXPECT_EQ(RobotOfSender(Origin{32767, 0xFFFFFFFFFFFF, 1}.SenderKey()), 32767);
  const Origin first{2, 5, 1}, second{2, 6, 1};
  EXPECT_NE(first.SenderKey(), second.SenderKey());  // two processes of robot 2
}

TEST(ReplayGuard, EachCounterOnceWithinTheLast1024AndNothingOlder) {
  ReplayGuard g;
  const auto take = [&](int robot, std::uint64_t instance, std::uint64_t counter) {
    return g.Take(Origin{robot, instance, counter});
  };
  EXPECT_TRUE(take(0, 9, 1));
  EXPECT_TRUE(take(0, 9, 3));
  EXPECT_FALSE(take(0, 9, 1));  // a repeat
  EXPECT_TRUE(take(0, 9, 2));   // late, not seen: taken
  EXPECT_FALSE(take(0, 9, 2));
  EXPECT_TRUE(take(1, 9, 1));   // another robot's counters are its own
  EXPECT_TRUE(take(0, 10, 1));  // another process of robot 0 too
  // 1026 is newest: 3 is 1023 behind (remembered), 2 and 1 are 1024 and 1025 behind (too old).
  EXPECT_TRUE(take(0, 9, 1026));
  EXPECT_FALSE(take(0, 9, 3));
  EXPECT_FALSE(take(0, 9, 2));
  EXPECT_TRUE(take(0, 9, 4));   // 1022 behind, never taken
  EXPECT_FALSE(take(0, 9, 4));
  // A jump of 64 moves whole words: 1026 is still remembered after it (4 is now too old).
  EXPECT_TRUE(take(0, 9, 1090));
  EXPECT_FALSE(take(0, 9, 1026));
  EXPECT_FALSE(take(0, 9, 1090));
  EXPECT_TRUE(take(0, 9, 1089));
  // A jump past the window forgets everything before it, and refuses it as too old.
  EXPECT_TRUE(take(0, 9, 100000));
  EXPECT_FALSE(take(0, 9, 1090));
  EXPECT_TRUE(take(0, 9, 99999));
}

TEST(ReplayGuard, RemembersAtMostItsSendersForgettingTheOneHeardLongestAgo) {
  ReplayGuard g(2);
  EXPECT_TRUE(g.Take(Origin{0, 1, 5}));
  EXPECT_TRUE(g.Take(Origin{1, 1, 5}));
  EXPECT_FALSE(g.Take(Origin{0, 1, 5}));  // heard again: now robot 1 is the oldest
  EXPECT_TRUE(g.Take(Origin{2, 1, 5}));   // robot 1 forgotten
  EXPECT_FALSE(g.Take(Origin{0, 1, 5}));
  EXPECT_TRUE(g.Take(Origin{1, 1, 5}));   // a new sender again
}

}  // namespace
}  // namespace dvpr::auth
