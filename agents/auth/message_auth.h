#pragma once
// Teammates that prove who they are (docs/security.md). Every message a launched team puts on
// its LCM group carries a trailer after the LCM-encoded message:
//
//   robot:u16 instance:u64 counter:u64 tag[16]            (34 bytes, integers big-endian)
//
// robot is the sender's robot id, instance a number its process drew at start (so two processes
// that claim one robot are told apart), counter counts its messages from 1. The tag is
// HMAC-SHA-256 with the team's secret (team_secret.h), truncated to its first 128 bits as
// RFC 4868 does for IPsec, over
//
//   "dvpr-tag-1" NUL channel NUL message robot instance counter
//
// so a message cannot be moved to another channel, relabelled as another robot's, or changed.
// A receiver drops a message whose tag does not verify before anything else looks at it
// (Open), and then a repeat of one it took: ReplayGuard remembers, per authenticated sender,
// which of its last 1024 counters it took, and refuses anything older.
//
// What this does not protect against: a teammate whose secret leaks (it can then speak for any
// robot), traffic analysis (sizes, times and channels are in the clear), and loss (anyone on the
// group can flood it, or spoil the fragments of a large message so that it fails its tag).
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string_view>
#include <utility>
#include <vector>

#include "agents/auth/team_secret.h"

namespace dvpr::auth {

inline constexpr std::size_t kTagBytes = 16;
inline constexpr std::size_t kTrailerBytes = 2 + 8 + 8 + kTagBytes;
inline constexpr int kMaxRobot = 32767;

// Who sent an authenticated message.
struct Origin {
  int robot = -1;
  std::uint64_t instance = 0;
  std::uint64_t counter = 0;
  // One number per sending process, never 0, with the robot in its top 16 bits
  // ((robot + 1) << 48): RobotOfSender gives it back. The low 48 bits are the instance's.
  std::uint64_t SenderKey() const;
};

// The robot of a SenderKey; -1 for a key that is not one (e.g. a socket's, udpm::Sender::Key()).
int RobotOfSender(std::uint64_t sender);

// A message whose tag verified: the LCM message without its trailer, and who sent it.
struct Opened {
  std::span<const std::uint8_t> message;
  Origin origin;
};

class MessageAuth {
 public:
  // robot: the robot this process speaks for, in [0, 32767], or -1 for a process that only
  // listens (Seal then throws). instance: 0 draws one.
  MessageAuth(const Secret& secret, int robot, std::uint64_t instance = 0);
  ~MessageAuth();
  MessageAuth(MessageAuth&&) noexcept;
  MessageAuth& operator=(MessageAuth&&) noexcept;

  // Appends the trailer to `message` (the LCM-encoded bytes published on `channel`).
  void Seal(std::string_view channel, std::vector<std::uint8_t>& message);
  // The message and its origin when `bytes` ends in a trailer whose tag verifies; nothing
  // otherwise (too short, another secret, any byte changed). Constant time in the tag.
  std::optional<Opened> Open(std::string_view channel, std::span<const std::uint8_t> bytes) const;

  int robot() const { return robot_; }
  std::uint64_t instance() const { return instance_; }
  std::uint64_t sealed() const { return counter_; }

 private:
  struct Mac;  // OpenSSL's HMAC context, keyed once
  void Tag(std::string_view channel, std::span<const std::uint8_t> message, std::span<const std::uint8_t, 18> fields,
           std::uint8_t* tag) const;

  std::unique_ptr<Mac> mac_;
  int robot_;
  std::uint64_t instance_;
  std::uint64_t counter_ = 0;
};

// Which authenticated messages were taken: per sender (robot and instance) the counters of its
// last 1024 messages. A counter taken before, or more than 1024 behind the newest, is refused.
// At most `max_senders` senders are remembered (the one heard longest ago is forgotten; only
// holders of the secret can add one).
class ReplayGuard {
 public:
  explicit ReplayGuard(std::size_t max_senders = 1024) : max_senders_(max_senders) {}
  // True the first time (origin's sender, counter) is seen within the window.
  bool Take(const Origin& origin);

 private:
  struct Window {
    std::uint64_t newest = 0;
    std::vector<std::uint64_t> bits = std::vector<std::uint64_t>(16, 0);  // bit d: newest - d taken
    std::uint64_t last_use = 0;
  };
  std::map<std::pair<int, std::uint64_t>, Window> windows_;
  std::size_t max_senders_;
  std::uint64_t uses_ = 0;
};

}  // namespace dvpr::auth
