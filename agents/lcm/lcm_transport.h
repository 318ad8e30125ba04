#pragma once
// Transport over real LCM (UDP multicast): the same agents, run as processes in wall-clock
// time. Timers and message handlers run on the thread that calls Run()/RunUntilWall(), so agent
// code needs no locks, as in the simulator.
//
// Publishing goes through liblcm; receiving does not. Debian's liblcm 1.3.1 writes out of
// bounds on a fragment whose offset wraps (one 233-byte datagram from anyone on the segment
// killed every agent; LCM pull request #628), so the transport reads the group itself, with the
// same wire format and the same socket options (agents/udpm/): lcm-spy, lcm-logger and other
// LCM programs on the URL keep working beside it. Only udpm:// URLs are taken. Every datagram
// is counted (ReceiveCounts): malformed ones and repeats of one already taken (the same sender
// and sequence number: a duplicating network) are dropped, never handed to a handler.
//
// A team's transport authenticates (Authenticate, agents/auth/message_auth.h): every message
// it publishes carries a tag made with the team's secret, and a message received on a channel it
// listens to is handed on only when its tag verifies and it is not a repeat of one taken from
// the same authenticated sender (AuthCounts); the handlers then see the message without its
// trailer and CurrentSender() names the authenticated process (auth::RobotOfSender gives its
// robot). Nothing of an unauthenticated message reaches the held channels, the replay guard or
// a handler.
//
// The agent clock: agent time = (wall time since the epoch) x speedup. The
// epoch is construction time until SetEpoch() moves it (a team starts
// together at an agreed wall-clock instant). Timers are kept in wall time, so
// moving the epoch does not move timers already scheduled; a timer scheduled
// before the epoch counts its delay from the epoch ("time stands still until
// the start"). A timer scheduled from inside a timer callback counts from that
// timer's due time, not from when the callback happened to run, so a periodic
// chain (a frame every 1/fps) does not drift when the process is scheduled
// late. Waits use ppoll() with nanosecond timeouts, so short service-time
// timers are not rounded up to whole milliseconds.
#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <queue>
#include <span>
#include <string>
#include <vector>

#include <lcm/lcm-cpp.hpp>

#include "agents/auth/message_auth.h"
#include "agents/messages/transport.h"
#include "agents/udpm/udpm_reassembler.h"
#include "agents/udpm/udpm_socket.h"
#include "agents/udpm/udpm_url.h"

namespace dvpr {

class LcmTransport final : public Transport {
 public:
  using WallClock = std::chrono::steady_clock;
  // Sees every publication.
  using Observer = std::function<void(const std::string& channel, std::span<const std::uint8_t> bytes)>;
  // Sees every message of a subscribed channel before it is decoded (once per
  // message, whatever the number of subscriptions), with its sender (udpm::Sender::Key());
  // false drops it unseen by the handlers (e.g. a well-formed message from outside the team).
  using Filter = std::function<bool(const std::string& channel, std::span<const std::uint8_t> bytes,
                                    std::uint64_t sender)>;

  // url: an LCM udpm URL, e.g. "udpm://239.255.76.67:7667?ttl=0"; empty uses LCM's default
  // (or $LCM_DEFAULT_URL). speedup > 1 runs the agent's clock faster than the wall clock
  // (frames at fps x speedup). limits: what reassembling fragments may hold.
  // Throws std::invalid_argument for a URL that is not udpm (udpm::ParseUrl) and
  // std::runtime_error, in one line, when the group cannot be opened.
  explicit LcmTransport(const std::string& url, double speedup = 1.0, udpm::Limits limits = {});
  ~LcmTransport() override;
  LcmTransport(const LcmTransport&) = delete;
  LcmTransport& operator=(const LcmTransport&) = delete;

  SimTime Now() const override;  // negative before the epoch
  // The wall-clock instant of agent time t (epoch + t / speedup), microseconds since 1970.
  std::int64_t UtimeAt(SimTime t) const override;
  void ScheduleAfter(SimTime delay, Callback fn) override;

  // Agent time 0 is the wall-clock instant `epoch` (may be in the future).
  void SetEpoch(std::chrono::system_clock::time_point epoch);
  double speedup() const { return speedup_; }

  // Handles messages and timers until Stop() is called or `deadline` (agent
  // clock) passes. Returns false when it stopped at the deadline.
  bool Run(SimTime deadline);
  // The same with a wall-clock deadline (status loops, barriers).
  bool RunUntilWall(WallClock::time_point deadline);
  void Stop() { stopped_ = true; }

  // From now on every publication is sealed and every message received must open (above). Call
  // before the loop runs first.
  void Authenticate(auth::MessageAuth auth);
  bool Authenticates() const { return auth_.has_value(); }

  // Publishes bytes as they are, typed or not, never sealed (tools, fault-injection tests).
  void PublishRaw(const std::string& channel, std::span<const std::uint8_t> bytes) {
    Send(channel, std::vector<std::uint8_t>(bytes.begin(), bytes.end()), bytes.size());
  }

  // Listens on `channels` now and keeps what arrives there until a handler subscribes; then the
  // kept messages are handled, in arrival order, as soon as the loop runs. A team's agents leave
  // the start barrier one by one (each when it has heard the others): a teammate that left
  // first may send before this agent subscribed, and UDP keeps nothing for a channel nobody
  // listens to, so without this the first queries of a loaded machine's slow agent were lost.
  // At most `max_bytes` (messages' bytes and 64 bytes of bookkeeping each, over all held
  // channels) are kept; what arrives past
  // that is dropped and counted (AuthCounts::held_dropped).
  static constexpr std::size_t kDefaultHoldBytes = std::size_t{16} << 20;
  void HoldUntilSubscribed(const std::vector<std::string>& channels, std::size_t max_bytes = kDefaultHoldBytes);
  void SetReceiveFilter(Filter fn) { on_receive_ = std::move(fn); }
  void SetPublishObserver(Observer fn) { on_publish_ = std::move(fn); }

  std::uint64_t Published() const { return published_; }
  std::uint64_t PublishedBytes() const { return published_bytes_; }
  std::uint64_t PublishFailures() const { return publish_failures_; }
  std::uint64_t Received() const { return received_; }
  // Every datagram read from the group, by what became of it.
  const udpm::Counts& ReceiveCounts() const { return reassembler_.counts(); }
  // Messages on the channels listened to that the team's tags refused, and held messages dropped.
  struct AuthCounts {
    std::uint64_t unauthenticated = 0;  // no trailer, another secret, a byte changed: dropped
    std::uint64_t replayed = 0;         // authenticated, but taken before (or too old to tell): dropped
    std::uint64_t held_dropped = 0;     // kept for a channel without its handler yet, past the bound
    std::size_t held_bytes_peak = 0;    // the most bytes held at once
  };
  const AuthCounts& auth_counts() const { return auth_counts_; }
  // Datagrams the kernel dropped because the receive buffer was full (read late).
  std::uint64_t KernelDropped() const { return socket_.kernel_dropped(); }
  // The sender (udpm::Sender::Key()) of the message being handled; 0 outside a handler.
  std::uint64_t CurrentSender() const { return current_sender_; }

 private:
  struct Timer {
    WallClock::time_point due;
    std::uint64_t seq;
    bool operator>(const Timer& o) const { return due != o.due ? due > o.due : seq > o.seq; }
  };
  struct Held {
    std::vector<std::uint8_t> bytes;
    std::uint64_t sender = 0;
  };
  struct ChannelSubscription {
    std::map<std::uint64_t, RawHandler> handlers;
    bool hold = false;       // HoldUntilSubscribed, no handler yet
    std::vector<Held> held;  // what arrived meanwhile
  };

  void DoPublish(const std::string& channel, const char* type_name, std::vector<std::uint8_t> bytes) override;
  // Publishes `bytes` as they are; the observer sees their first `message` bytes.
  void Send(const std::string& channel, const std::vector<std::uint8_t>& bytes, std::size_t message);
  std::uint64_t DoSubscribe(const std::string& channel, RawHandler handler) override;
  void DoUnsubscribe(std::uint64_t id) override;
  // Reads and handles what waits on the socket (a bounded number of datagrams).
  void ReceiveWaiting();
  void Dispatch(const std::string& channel, std::span<const std::uint8_t> bytes, std::uint64_t sender);
  void RunDueTimers();
  void WaitAndHandle(WallClock::duration wait);
  WallClock::duration ToWall(SimTime agent) const;

  udpm::Url url_;
  udpm::Socket socket_;
  udpm::Reassembler reassembler_;
  std::vector<std::uint8_t> datagram_;
  std::optional<auth::MessageAuth> auth_;
  auth::ReplayGuard replay_;
  AuthCounts auth_counts_;
  std::size_t hold_limit_ = kDefaultHoldBytes;
  std::size_t held_bytes_ = 0;
  std::unique_ptr<lcm::LCM> lcm_;  // publishing only: it never subscribes, so it never receives
  std::uint64_t current_sender_ = 0;
  double speedup_;
  WallClock::time_point zero_;
  std::int64_t zero_utime_;  // zero_ on the system clock, microseconds since the Unix epoch
  std::optional<WallClock::time_point> running_due_;  // due time of the timer being run
  std::priority_queue<Timer, std::vector<Timer>, std::greater<>> timers_;
  std::map<std::uint64_t, Callback> timer_callbacks_;
  // The channels listened to; handlers by subscription id. Removing a handler while it runs is
  // safe: handlers are copied before being called. std::less<>: looked up by string_view.
  std::map<std::string, ChannelSubscription, std::less<>> channels_;
  std::map<std::uint64_t, std::string> channel_of_;
  Filter on_receive_;
  Observer on_publish_;
  std::uint64_t next_id_ = 1;
  bool stopped_ = false;
  std::uint64_t published_ = 0;
  std::uint64_t published_bytes_ = 0;
  std::uint64_t publish_failures_ = 0;
  std::uint64_t received_ = 0;
};

}  // namespace dvpr
