// LCM's UDP multicast protocol read without trusting the network: datagrams built by hand
// (datagram_builder.h) against the rules of agents/udpm/udpm_datagram.h, reassembly and its
// limits, duplicates, and the URLs a team accepts.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <numeric>
#include <random>
#include <stdexcept>
#include <string>

#include "agents/udpm/udpm_datagram.h"
#include "agents/udpm/udpm_reassembler.h"
#include "agents/udpm/udpm_url.h"
#include "tests/agents/udpm/datagram_builder.h"

namespace dvpr::udpm {
namespace {

using udpm_test::Bytes;
using udpm_test::Fragment;
using udpm_test::Small;

const Sender kAlice{0x7f000001, 40000};
const Sender kBob{0x7f000001, 40001};

std::string Text(std::span<const std::uint8_t> b) { return std::string(b.begin(), b.end()); }
Bytes Of(const std::string& s) { return Bytes(s.begin(), s.end()); }

// --- one datagram ---

TEST(UdpmDatagram, ReadsASmallMessage) {
  const Bytes b = Small(7, "DVPR_MATCH_3", {1, 2, 3});
  ASSERT_EQ(b.size(), 8u + 12u + 1u + 3u);
  const Datagram d = ParseDatagram(b);
  ASSERT_EQ(d.kind, DatagramKind::kShort) << d.problem;
  EXPECT_EQ(d.seqno, 7u);
  EXPECT_EQ(d.channel, "DVPR_MATCH_3");
  EXPECT_EQ(d.bytes.size(), 3u);
  EXPECT_EQ(d.bytes[2], 3);
  // An empty payload is a message of 0 bytes (the channel's decoder refuses it, not the wire).
  EXPECT_EQ(ParseDatagram(Small(1, "C", {})).kind, DatagramKind::kShort);
}

TEST(UdpmDatagram, ReadsFragmentsAndTheChannelOfFragmentZero) {
  const Bytes first_bytes = Fragment(9, 10, 0, 0, 2, "CH", Of("abcdef"));
  const Datagram first = ParseDatagram(first_bytes);  // its views point into first_bytes
  ASSERT_EQ(first.kind, DatagramKind::kFragment) << first.problem;
  EXPECT_EQ(first.seqno, 9u);
  EXPECT_EQ(first.message_size, 10u);
  EXPECT_EQ(first.fragments, 2);
  EXPECT_EQ(first.channel, "CH");
  EXPECT_EQ(Text(first.bytes), "abcdef");
  // The last 4 of 10 bytes fit exactly; 5 would run one past the end.
  const Bytes last_bytes = Fragment(9, 10, 6, 1, 2, "", Of("ghij"));
  const Datagram last = ParseDatagram(last_bytes);
  ASSERT_EQ(last.kind, DatagramKind::kFragment) << last.problem;
  EXPECT_EQ(last.offset, 6u);
  EXPECT_TRUE(last.channel.empty());
  EXPECT_EQ(ParseDatagram(Fragment(9, 10, 6, 1, 2, "", Of("ghijk"))).kind, DatagramKind::kMalformed);
}

TEST(UdpmDatagram, TheWrappingOffsetOfIssue31IsMalformed) {
  const Bytes crafted = udpm_test::WrappingFragment();
  ASSERT_EQ(crafted.size(), 233u);
  const Datagram d = ParseDatagram(crafted);
  EXPECT_EQ(d.kind, DatagramKind::kMalformed);
  EXPECT_STREQ(d.problem, "fragment outside its message");
  // LCM pull request #628's example: offset 0xFFFFFFF0 + 32 bytes "fits" a 1024-byte message
  // in 32-bit arithmetic (it wraps to 16).
  EXPECT_EQ(ParseDatagram(Fragment(1, 1024, 0xFFFFFFF0u, 1, 2, "", Bytes(32, 0))).kind, DatagramKind::kMalformed);
}

TEST(UdpmDatagram, TruncatedHeadersAreMalformed) {
  const Bytes small = Small(1, "C", {});
  for (std::size_t n = 0; n < 8; ++n) {
    EXPECT_EQ(ParseDatagram(std::span(small).first(n)).kind, DatagramKind::kMalformed) << n << " bytes";
  }
  const Bytes fragment = Fragment(1, 100, 50, 1, 2, "", Bytes(10, 0));
  for (std::size_t n = 8; n < 20; ++n) {
    EXPECT_EQ(ParseDatagram(std::span(fragment).first(n)).kind, DatagramKind::kMalformed) << n << " bytes";
  }
  EXPECT_EQ(ParseDatagram(std::span(fragment).first(20)).kind, DatagramKind::kMalformed);  // no bytes
  EXPECT_EQ(ParseDatagram(std::span(fragment).first(21)).kind, DatagramKind::kFragment);
}

TEST(UdpmDatagram, ChannelsMustEndWithinLcmsLimit) {
  EXPECT_EQ(ParseDatagram(Small(1, std::string(63, 'x'), {1})).kind, DatagramKind::kShort);
  EXPECT_EQ(ParseDatagram(Small(1, std::string(64, 'x'), {1})).kind, DatagramKind::kMalformed);
  EXPECT_EQ(ParseDatagram(Small(1, "", {1})).kind, DatagramKind::kMalformed);
  Bytes no_nul{'L', 'C', '0', '2', 0, 0, 0, 1, 'A', 'B'};
  EXPECT_STREQ(ParseDatagram(no_nul).problem, "channel without its terminating NUL");
  EXPECT_EQ(ParseDatagram(Fragment(1, 100, 0, 0, 2, std::string(64, 'x'), {1})).kind, DatagramKind::kMalformed);
  EXPECT_EQ(ParseDatagram(Fragment(1, 100, 0, 0, 2, std::string(63, 'x'), {1})).kind, DatagramKind::kFragment);
  EXPECT_EQ(ParseDatagram(Bytes{'X', 'C', '0', '2', 0, 0, 0, 1, 'A', 0}).kind, DatagramKind::kMalformed);
}

TEST(UdpmDatagram, FragmentHeadersThatCannotDescribeAMessageAreMalformed) {
  const auto problem = [](const Bytes& b) { return std::string(ParseDatagram(b).problem); };
  EXPECT_EQ(problem(Fragment(1, 0, 0, 1, 2, "", {1})), "fragmented message of 0 bytes");
  EXPECT_EQ(problem(Fragment(1, (1u << 28) + 1, 0, 1, 2, "", {1})), "message larger than LCM's 2^28 bytes");
  EXPECT_EQ(problem(Fragment(1, 100, 0, 1, 0, "", {1})), "message of 0 fragments");
  EXPECT_EQ(problem(Fragment(1, 100, 0, 2, 2, "", {1})), "fragment number not below the fragment count");
  EXPECT_EQ(problem(Fragment(1, 3, 0, 1, 4, "", {1})), "more fragments than the message has bytes");
  EXPECT_EQ(problem(Fragment(1, 100, 5, 0, 2, "C", {1})), "fragment 0 not at offset 0");
  EXPECT_EQ(problem(Fragment(1, 100, 100, 1, 2, "", {1})), "fragment outside its message");
  EXPECT_EQ(ParseDatagram(Fragment(1, 1u << 28, (1u << 28) - 1, 1, 2, "", {1})).kind, DatagramKind::kFragment);
}

// --- reassembly ---

const Clock::time_point kT0{};

TEST(UdpmReassembler, PutsFragmentsTogetherInAnyOrder) {
  for (const bool reversed : {false, true}) {
    Reassembler r;
    const Bytes a = Fragment(5, 10, 0, 0, 3, "CH", Of("abcd")), b = Fragment(5, 10, 4, 1, 3, "", Of("efg")),
                c = Fragment(5, 10, 7, 2, 3, "", Of("hij"));
    std::optional<Message> m;
    for (const Bytes* d : reversed ? std::vector<const Bytes*>{&c, &b, &a} : std::vector<const Bytes*>{&a, &b, &c}) {
      EXPECT_FALSE(m) << "complete before its last fragment";
      m = r.Take(kAlice, *d, kT0);
    }
    ASSERT_TRUE(m);
    EXPECT_EQ(m->channel, "CH");
    EXPECT_EQ(Text(m->payload), "abcdefghij");
    EXPECT_EQ(m->seqno, 5u);
    EXPECT_EQ(m->sender, kAlice);
    EXPECT_EQ(r.counts().messages, 1u);
    EXPECT_EQ(r.counts().datagrams, 3u);
    EXPECT_EQ(r.partial_messages(), 0u);
    EXPECT_EQ(r.partial_bytes(), 0u);
  }
}

TEST(UdpmReassembler, DuplicatesAreCountedAndTakenOnce) {
  Reassembler r;
  const Bytes small = Small(1, "CH", {42});
  EXPECT_TRUE(r.Take(kAlice, small, kT0));
  EXPECT_FALSE(r.Take(kAlice, small, kT0));  // the same sender and number again
  EXPECT_TRUE(r.Take(kBob, small, kT0));     // another sender's number 1
  // A fragment repeated before its message completes, then the whole message repeated.
  const Bytes a = Fragment(2, 4, 0, 0, 2, "CH", Of("ab")), b = Fragment(2, 4, 2, 1, 2, "", Of("cd"));
  EXPECT_FALSE(r.Take(kAlice, a, kT0));
  EXPECT_FALSE(r.Take(kAlice, a, kT0));
  const auto m = r.Take(kAlice, b, kT0);
  ASSERT_TRUE(m);
  EXPECT_EQ(Text(m->payload), "abcd");
  EXPECT_FALSE(r.Take(kAlice, a, kT0));
  EXPECT_FALSE(r.Take(kAlice, b, kT0));
  EXPECT_EQ(r.counts().datagrams, 8u);
  EXPECT_EQ(r.counts().duplicates, 4u);
  EXPECT_EQ(r.counts().messages, 3u);
  EXPECT_EQ(r.counts().malformed, 0u);
  EXPECT_EQ(r.partial_messages(), 0u);  // the late repeats opened no new partial message
}

TEST(UdpmReassembler, RemembersTheLast1024NumbersOfEachSenderAcrossTheWrap) {
  Reassembler r;
  for (std::uint32_t s = 0; s < 1500; ++s) ASSERT_TRUE(r.Take(kAlice, Small(s, "C", {}), kT0));
  EXPECT_FALSE(r.Take(kAlice, Small(1499, "C", {}), kT0));  // the newest
  EXPECT_FALSE(r.Take(kAlice, Small(476, "C", {}), kT0));   // 1023 behind it: still remembered
  EXPECT_TRUE(r.Take(kAlice, Small(475, "C", {}), kT0));    // 1024 behind: taken (a restart looks like this)
  Reassembler w;
  for (const std::uint32_t s : {0xFFFFFFFEu, 0xFFFFFFFFu, 0u, 1u}) ASSERT_TRUE(w.Take(kAlice, Small(s, "C", {}), kT0));
  for (const std::uint32_t s : {0xFFFFFFFEu, 0xFFFFFFFFu, 0u, 1u}) EXPECT_FALSE(w.Take(kAlice, Small(s, "C", {}), kT0)) << s;
  EXPECT_EQ(w.counts().duplicates, 4u);
  // A jump forward of more than the window forgets everything before it.
  EXPECT_TRUE(w.Take(kAlice, Small(5000, "C", {}), kT0));
  EXPECT_TRUE(w.Take(kAlice, Small(1, "C", {}), kT0));
}

TEST(UdpmReassembler, FragmentsThatDisagreeWithTheirMessageAreMalformed) {
  Reassembler r;
  EXPECT_FALSE(r.Take(kAlice, Fragment(3, 9, 0, 0, 3, "CH", Of("abc")), kT0));
  EXPECT_FALSE(r.Take(kAlice, Fragment(3, 9, 3, 1, 2, "", Of("def")), kT0));   // 2 fragments, not 3
  EXPECT_FALSE(r.Take(kAlice, Fragment(3, 12, 3, 1, 3, "", Of("def")), kT0));  // 12 bytes, not 9
  EXPECT_FALSE(r.Take(kAlice, Fragment(3, 9, 2, 1, 3, "", Of("xyz")), kT0));   // overlaps "abc"
  EXPECT_EQ(r.counts().malformed, 3u);
  EXPECT_FALSE(r.Take(kAlice, Fragment(3, 9, 3, 1, 3, "", Of("def")), kT0));
  const auto m = r.Take(kAlice, Fragment(3, 9, 6, 2, 3, "", Of("ghi")), kT0);
  ASSERT_TRUE(m);
  EXPECT_EQ(Text(m->payload), "abcdefghi");
  // Every number in but the bytes short of the size (a gap): malformed, dropped.
  EXPECT_FALSE(r.Take(kAlice, Fragment(4, 9, 0, 0, 2, "CH", Of("ab")), kT0));
  EXPECT_FALSE(r.Take(kAlice, Fragment(4, 9, 5, 1, 2, "", Of("fghi")), kT0));
  EXPECT_EQ(r.counts().malformed, 4u);
  EXPECT_EQ(r.partial_messages(), 0u);
}

TEST(UdpmReassembler, AMessageAboveTheLimitIsMalformedAndAllocatesNothing) {
  Limits limits;
  limits.max_message_bytes = 1000;
  Reassembler r(limits);
  EXPECT_FALSE(r.Take(kAlice, Fragment(1, 1001, 0, 0, 2, "CH", Of("ab")), kT0));
  EXPECT_EQ(r.counts().malformed, 1u);
  EXPECT_EQ(r.partial_bytes(), 0u);
  EXPECT_EQ(r.senders(), 0u);  // nothing kept of a malformed datagram, not even its sender
  // A fragment claiming the largest size LCM allows keeps only the bytes it brought.
  Reassembler big;
  EXPECT_FALSE(big.Take(kAlice, Fragment(1, 1u << 26, 0, 0, 2, "CH", Of("ab")), kT0));
  EXPECT_EQ(big.partial_messages(), 1u);
  EXPECT_LT(big.partial_bytes(), 1000u);
}

TEST(UdpmReassembler, KeepsABoundedNumberOfPartialMessagesPerSender) {
  Limits limits;
  limits.partials_per_sender = 2;
  Reassembler r(limits);
  for (std::uint32_t s = 1; s <= 3; ++s) {
    EXPECT_FALSE(r.Take(kAlice, Fragment(s, 4, 0, 0, 2, "CH", Of("ab")), kT0 + std::chrono::milliseconds(s)));
  }
  EXPECT_EQ(r.partial_messages(), 2u);
  EXPECT_EQ(r.counts().incomplete, 1u);  // message 1, the oldest, made room for message 3
  EXPECT_FALSE(r.Take(kAlice, Fragment(1, 4, 2, 1, 2, "", Of("cd")), kT0));  // its end opens a new one
  EXPECT_TRUE(r.Take(kAlice, Fragment(3, 4, 2, 1, 2, "", Of("cd")), kT0));
}

TEST(UdpmReassembler, DropsStalePartialMessages) {
  Reassembler r;
  EXPECT_FALSE(r.Take(kAlice, Fragment(1, 4, 0, 0, 2, "CH", Of("ab")), kT0));
  EXPECT_GT(r.partial_bytes(), 0u);
  EXPECT_TRUE(r.Take(kBob, Small(1, "CH", {}), kT0 + std::chrono::seconds(1)));
  EXPECT_EQ(r.partial_messages(), 1u);  // 1 s: not stale yet (the timeout is 2 s)
  EXPECT_TRUE(r.Take(kBob, Small(2, "CH", {}), kT0 + std::chrono::seconds(3)));
  EXPECT_EQ(r.partial_messages(), 0u);
  EXPECT_EQ(r.partial_bytes(), 0u);
  EXPECT_EQ(r.counts().incomplete, 1u);
  // Its last fragment, late, starts a message of its own that never completes.
  EXPECT_FALSE(r.Take(kAlice, Fragment(1, 4, 2, 1, 2, "", Of("cd")), kT0 + std::chrono::seconds(3)));
}

TEST(UdpmReassembler, RemembersABoundedNumberOfSenders) {
  Limits limits;
  limits.max_senders = 2;
  Reassembler r(limits);
  for (std::uint16_t port = 1; port <= 3; ++port) {
    EXPECT_FALSE(r.Take(Sender{1, port}, Fragment(1, 4, 0, 0, 2, "CH", Of("ab")), kT0 + std::chrono::milliseconds(port)));
  }
  EXPECT_EQ(r.senders(), 2u);
  EXPECT_EQ(r.counts().incomplete, 1u);  // sender 1, heard longest ago, and its partial message
  EXPECT_EQ(r.partial_messages(), 2u);
}

TEST(UdpmReassembler, PartialBytesStayWithinTheirLimitUnderAFloodOfTinyFragments) {
  Limits limits;
  limits.max_message_bytes = 1000;
  limits.max_partial_bytes = 1000 + 65535 * 128 + 256;  // the smallest Validate takes
  Reassembler r(limits);
  std::uint64_t count = 0;
  for (std::uint16_t port = 0; port < 200; ++port) {
    for (std::uint16_t f = 1; f < 1000; ++f) {
      r.Take(Sender{2, port}, Fragment(port, 1000, f, f, 1000, "", {1}), kT0);
      ++count;
      ASSERT_LE(r.partial_bytes(), limits.max_partial_bytes);
    }
  }
  EXPECT_EQ(r.counts().datagrams, count);
  EXPECT_GT(r.counts().incomplete, 0u);  // the oldest made room
}

TEST(UdpmReassembler, LimitsThatCannotHoldTheirLargestMessageAreRefused) {
  Limits limits;
  limits.max_partial_bytes = limits.max_message_bytes;
  EXPECT_THROW(limits.Validate(), std::invalid_argument);
  limits = Limits{};
  limits.max_message_bytes = (1u << 28) + 1;
  EXPECT_THROW(limits.Validate(), std::invalid_argument);
  limits = Limits{};
  limits.partials_per_sender = 0;
  EXPECT_THROW(limits.Validate(), std::invalid_argument);
  EXPECT_NO_THROW(Limits{}.Validate());
}

// The crafted datagram and 10^5 datagrams malformed by construction, from 1000 senders: every
// one counted malformed, no message, nothing kept.
TEST(UdpmReassembler, TheWrappingFragmentAndAHundredThousandHostileDatagramsAreAllMalformed) {
  Reassembler r;
  EXPECT_FALSE(r.Take(kAlice, udpm_test::WrappingFragment(), kT0));
  udpm_test::HostileDatagrams hostile(31);
  for (int i = 0; i < 100000; ++i) {
    const Bytes d = hostile.Next();
    ASSERT_FALSE(r.Take(Sender{3, static_cast<std::uint16_t>(i % 1000)}, d, kT0)) << "datagram " << i;
  }
  EXPECT_EQ(r.counts().datagrams, 100001u);
  EXPECT_EQ(r.counts().malformed, 100001u);
  EXPECT_EQ(r.counts().messages, 0u);
  EXPECT_EQ(r.partial_bytes(), 0u);
  EXPECT_EQ(r.senders(), 0u);
}

// Well-formed streams of four senders with bytes flipped, cut, repeated and reordered at random:
// whatever comes, the counts add up and the memory stays within its limits.
TEST(UdpmReassembler, MutatedStreamsKeepCountsAndLimits) {
  Limits limits;
  limits.max_message_bytes = 5000;
  limits.max_partial_bytes = 5000 + 65535 * 128 + 256;
  limits.partials_per_sender = 3;
  limits.max_senders = 3;
  Reassembler r(limits);
  std::mt19937_64 random(32);
  std::uint64_t delivered = 0;
  Clock::time_point now = kT0;
  for (int i = 0; i < 100000;) {
    const auto seqno = static_cast<std::uint32_t>(random() % 64);
    const std::uint32_t size = 1 + static_cast<std::uint32_t>(random() % 4000);
    const std::uint16_t fragments = static_cast<std::uint16_t>(1 + random() % 4);
    std::vector<Bytes> stream;
    std::uint32_t offset = 0;
    for (std::uint16_t f = 0; f < fragments; ++f) {
      const std::uint32_t part = f + 1 == fragments ? size - offset : std::min(size - offset - (fragments - f - 1), size / fragments);
      if (part == 0) break;
      stream.push_back(Fragment(seqno, size, offset, f, fragments, "CH", Bytes(part, static_cast<std::uint8_t>(f))));
      offset += part;
    }
    for (Bytes& d : stream) {
      switch (random() % 6) {
        case 0: d[random() % d.size()] ^= static_cast<std::uint8_t>(1 + random() % 255); break;
        case 1: d.resize(random() % d.size()); break;
        case 2: std::swap(d, stream[random() % stream.size()]); break;
        default: break;
      }
    }
    for (const Bytes& d : stream) {
      const Sender from{4, static_cast<std::uint16_t>(random() % 4)};
      now += std::chrono::milliseconds(random() % 50);
      const int repeats = random() % 8 == 0 ? 2 : 1;
      for (int k = 0; k < repeats; ++k, ++i) {
        if (const auto m = r.Take(from, d, now)) {
          ++delivered;
          ASSERT_LE(m->payload.size(), limits.max_message_bytes);
          ASSERT_FALSE(m->channel.empty());
        }
        ASSERT_LE(r.partial_bytes(), limits.max_partial_bytes);
        ASSERT_LE(r.senders(), 3u);
        ASSERT_LE(r.partial_messages(), 9u);
      }
    }
  }
  const Counts& c = r.counts();
  EXPECT_EQ(c.messages, delivered);
  EXPECT_LE(c.malformed + c.duplicates, c.datagrams);
  EXPECT_GT(c.messages, 0u);
  EXPECT_GT(c.malformed, 0u);
  EXPECT_GT(c.duplicates, 0u);
}

// --- URLs ---

TEST(UdpmUrl, ReadsGroupPortAndOptions) {
  const Url u = ParseUrl("udpm://239.255.76.68:7700?ttl=1&recv_buf_size=4194304");
  EXPECT_EQ(u.group, 0xEFFF4C44u);
  EXPECT_EQ(u.port, 7700);
  EXPECT_EQ(u.ttl, 1);
  EXPECT_EQ(u.recv_buf_size, 4194304);
  const Url d = ParseUrl("udpm://");
  EXPECT_EQ(d.group, 0xEFFF4C43u);  // LCM's 239.255.76.67:7667
  EXPECT_EQ(d.port, 7667);
  EXPECT_EQ(d.ttl, 0);
  EXPECT_FALSE(d.recv_buf_size);
}

TEST(UdpmUrl, RefusesEverythingButUdpMulticast) {
  for (const char* url : {"file:///tmp/x.log?mode=w", "memq://", "tcpq://localhost:7700", "239.255.76.67:7667",
                          "udpm://10.0.0.1:7667", "udpm://239.255.76:7667", "udpm://239.255.76.67:0",
                          "udpm://239.255.76.67:70000", "udpm://239.255.76.67:7667?ttl=256",
                          "udpm://239.255.76.67:7667?ttl=", "udpm://239.255.76.67:7667?recv_buf_size=0",
                          "udpm://239.255.76.67:7667?transmit_only=1"}) {
    EXPECT_THROW(ParseUrl(url), std::invalid_argument) << url;
  }
  try {
    ParseUrl("file:///tmp/x.log?mode=w");
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "LCM URL 'file:///tmp/x.log?mode=w': only the udpm provider (UDP multicast) "
                                     "connects a team of processes, got 'file'");
  }
}

}  // namespace
}  // namespace dvpr::udpm
