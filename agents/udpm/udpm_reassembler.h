#pragma once
// The receiving half of LCM's UDP multicast protocol above the socket: each datagram is
// classified (udpm_datagram.h), a repeat of one already taken is recognised by its sender and
// sequence number, and fragments are put together into messages, all within hard limits, so
// that what any sender puts on the group costs a bounded amount of memory and time:
//
// - a message may claim at most `max_message_bytes`; a fragment's bytes are kept as they come
//   (a claimed size allocates nothing), charged with their bookkeeping against
//   `max_partial_bytes` over all senders; when a new fragment would exceed it, the least
//   recently extended partial messages are dropped first;
// - each sender has at most `partials_per_sender` messages in progress (the oldest is dropped
//   for a new one); a partial message nothing was added to for `partial_timeout` is dropped;
// - at most `max_senders` senders are remembered (the one heard longest ago is forgotten);
// - per sender the sequence numbers of the last 1024 messages taken are remembered: a datagram
//   of one of them (unless Limits::drop_repeats is off), or a fragment already held, is a
//   duplicate. A number more than 1024 behind
//   the newest is taken (a sender that restarted on the same port numbers from 0 again).
//
// Every datagram is counted once: malformed, duplicate, or taken; a message that completes
// counts in `messages`, a partial dropped before completing in `incomplete`. A fragment that
// disagrees with the others of its message (size, count, overlapping bytes) is malformed.
#include <array>
#include <chrono>
#include <cstdint>
#include <list>
#include <map>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "agents/udpm/udpm_datagram.h"

namespace dvpr::udpm {

using Clock = std::chrono::steady_clock;

// A sending socket: IPv4 address and port, in host byte order.
struct Sender {
  std::uint32_t address = 0;
  std::uint16_t port = 0;
  // One number per sender, never 0 (0 means "no sender").
  std::uint64_t Key() const { return (std::uint64_t{address} << 16 | port) + 1; }
  bool operator==(const Sender&) const = default;
};

struct Limits {
  std::uint32_t max_message_bytes = 64u << 20;
  std::size_t max_partial_bytes = std::size_t{128} << 20;
  int partials_per_sender = 4;
  int max_senders = 256;
  Clock::duration partial_timeout = std::chrono::seconds(2);
  // Whether a message whose sender and sequence number were taken before is dropped here. A
  // receiver that authenticates its messages (agents/auth/) turns this off and drops repeats
  // after the tag verified, keyed on the authenticated sender: keyed on the socket, 64 forged
  // datagrams from a teammate's address and port made its next genuine messages "repeats".
  bool drop_repeats = true;
  void Validate() const;  // throws std::invalid_argument naming the field
};

struct Counts {
  std::uint64_t datagrams = 0;   // every datagram given to Take
  std::uint64_t malformed = 0;   // of which malformed (or disagreeing with their message)
  std::uint64_t duplicates = 0;  // of which repeats of a message or fragment already taken
  std::uint64_t messages = 0;    // complete messages handed out
  std::uint64_t incomplete = 0;  // partial messages dropped (limits, timeout) before completing
};

struct Message {
  std::string_view channel;
  std::span<const std::uint8_t> payload;
  Sender sender;
  std::uint32_t seqno = 0;
};

class Reassembler {
 public:
  explicit Reassembler(Limits limits = {});

  // Takes one datagram from `sender`, received at `now`. Returns the message it completes
  // (a small message at once); its views are valid until the next call and while `datagram`
  // is.
  std::optional<Message> Take(const Sender& sender, std::span<const std::uint8_t> datagram, Clock::time_point now);

  const Counts& counts() const { return counts_; }
  const Limits& limits() const { return limits_; }
  std::size_t partial_messages() const;
  std::size_t partial_bytes() const { return partial_bytes_; }  // kept bytes and their bookkeeping
  std::size_t senders() const { return senders_.size(); }

 private:
  // Which of the last 1024 sequence numbers of one sender were taken.
  class SeqnoWindow {
   public:
    bool Seen(std::uint32_t seqno) const;
    void Mark(std::uint32_t seqno);

   private:
    static constexpr std::uint32_t kSpan = 1024;
    bool any_ = false;
    std::uint32_t newest_ = 0;
    std::array<std::uint64_t, kSpan / 64> bits_{};  // bit d: newest_ - d was taken
  };
  struct Partial {
    std::uint32_t seqno = 0;
    std::uint32_t message_size = 0;
    std::uint16_t fragments = 0;
    std::string channel;                                   // from fragment 0
    std::map<std::uint32_t, std::vector<std::uint8_t>> by_offset;
    std::set<std::uint16_t> numbers;                       // fragment numbers held
    std::size_t kept = 0;                                  // bytes held
    std::size_t charge = 0;                                // kept + bookkeeping
    Clock::time_point last;
  };
  struct SenderState {
    SeqnoWindow taken;
    std::list<Partial> partials;  // a list: dropping one keeps references to the others
    Clock::time_point last_heard;
  };

  SenderState& StateOf(const Sender& sender, Clock::time_point now);
  std::optional<Message> TakeFragment(const Sender& sender, SenderState& state, const Datagram& d,
                                      Clock::time_point now);
  // Adds d's bytes to p, unless p holds that fragment already or d disagrees with what p
  // holds (another size or count, bytes overlapping others).
  enum class Added { kYes, kDuplicate, kDisagrees };
  Added Add(Partial& p, const Datagram& d, Clock::time_point now);
  void MakeRoom(std::size_t bytes, const Partial* keep);
  void DropStale(Clock::time_point now);
  void Drop(SenderState& state, std::list<Partial>::iterator partial, bool lost);

  Limits limits_;
  Counts counts_;
  std::unordered_map<std::uint64_t, SenderState> senders_;
  std::size_t partial_bytes_ = 0;
  Clock::time_point next_sweep_{};
  std::vector<std::uint8_t> completed_;  // the last message put together
  std::string completed_channel_;
};

}  // namespace dvpr::udpm
