#include "agents/lcm/lcm_transport.h"

#include <poll.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string_view>

namespace dvpr {

namespace {

std::int64_t SystemUtime(std::chrono::system_clock::time_point t) {
  return std::chrono::duration_cast<std::chrono::microseconds>(t.time_since_epoch()).count();
}

// What a held message costs: its bytes and its bookkeeping (a flood of empty messages is bounded too).
std::size_t HeldCharge(std::size_t bytes) { return bytes + 64; }

// At most this many datagrams are read per wait, so that timers due meanwhile are not held up
// by a flood.
constexpr int kDatagramsPerWait = 64;

// Runs `open` with this process's stderr going to a temporary file and returns what was written
// there: liblcm reports a failure in several lines of its own on stderr (perror, a routing
// table hint), which the user should see as one dvpr line.
template <typename Open>
std::string CapturingStderr(Open open) {
  std::fflush(stderr);
  std::FILE* sink = std::tmpfile();
  const int saved = sink != nullptr ? dup(STDERR_FILENO) : -1;
  if (saved < 0 || dup2(fileno(sink), STDERR_FILENO) < 0) {
    if (saved >= 0) close(saved);
    if (sink != nullptr) std::fclose(sink);
    open();  // no capture: better liblcm's lines than no agent
    return "";
  }
  struct Restore {
    int saved;
    ~Restore() {
      std::fflush(stderr);
      dup2(saved, STDERR_FILENO);
      close(saved);
    }
  };
  {
    const Restore restore{saved};
    open();
  }
  std::string text;
  std::rewind(sink);
  char chunk[512];
  for (std::size_t n; (n = std::fread(chunk, 1, sizeof chunk, sink)) > 0;) text.append(chunk, n);
  std::fclose(sink);
  return text;
}

// liblcm's first non-empty line, trimmed ("connect: Network is unreachable").
std::string FirstLine(std::string_view text) {
  while (!text.empty()) {
    const auto end = text.find('\n');
    std::string_view line = text.substr(0, end);
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.remove_suffix(1);
    if (!line.empty()) return std::string(line);
    if (end == std::string_view::npos) break;
    text.remove_prefix(end + 1);
  }
  return "no reason given";
}

std::unique_ptr<lcm::LCM> OpenPublisher(const udpm::Url& url) {
  std::unique_ptr<lcm::LCM> lcm;
  const std::string said = CapturingStderr([&] { lcm = std::make_unique<lcm::LCM>(url.text); });
  if (!lcm->good()) {
    throw std::runtime_error("LCM could not open '" + url.text + "' for publishing: " + FirstLine(said) +
                             " (for this machine alone the loopback interface needs multicast and a route for "
                             "224.0.0.0/4: README, \"Running real agents\")");
  }
  return lcm;
}

}  // namespace

LcmTransport::LcmTransport(const std::string& url, double speedup, udpm::Limits limits)
    : url_(udpm::ParseUrl(url)), socket_(url_), reassembler_(limits), datagram_(udpm::kDatagramBufferBytes),
      lcm_(OpenPublisher(url_)), speedup_(speedup), zero_(WallClock::now()),
      zero_utime_(SystemUtime(std::chrono::system_clock::now())) {
  if (!(speedup > 0.0) || !std::isfinite(speedup)) {
    throw std::invalid_argument("LcmTransport: speedup must be a positive number");
  }
}

LcmTransport::~LcmTransport() = default;

LcmTransport::WallClock::duration LcmTransport::ToWall(SimTime agent) const {
  const double ns = static_cast<double>(agent.ns()) / speedup_;
  return std::chrono::duration_cast<WallClock::duration>(std::chrono::nanoseconds(std::llround(ns)));
}

SimTime LcmTransport::Now() const {
  const auto wall = std::chrono::duration_cast<std::chrono::nanoseconds>(WallClock::now() - zero_);
  return SimTime::Nanos(std::llround(static_cast<double>(wall.count()) * speedup_));
}

void LcmTransport::SetEpoch(std::chrono::system_clock::time_point epoch) {
  // steady_clock cannot be set, system_clock can: convert once, now. The two clocks are read
  // between two steady readings, and again when the process was preempted in between (the
  // conversion would be off by the preemption: a team's clocks must agree to well under a frame).
  WallClock::time_point before, after;
  std::chrono::system_clock::time_point system;
  for (int attempt = 0; attempt < 10; ++attempt) {
    before = WallClock::now();
    system = std::chrono::system_clock::now();
    after = WallClock::now();
    if (after - before < std::chrono::microseconds(100)) break;
  }
  zero_ = before + (after - before) / 2 + std::chrono::duration_cast<WallClock::duration>(epoch - system);
  zero_utime_ = SystemUtime(epoch);
}

std::int64_t LcmTransport::UtimeAt(SimTime t) const {
  return zero_utime_ + std::llround(static_cast<double>(t.ns()) / speedup_ / 1000.0);
}

void LcmTransport::ScheduleAfter(SimTime delay, Callback fn) {
  const std::uint64_t id = next_id_++;
  const WallClock::time_point base = std::max(running_due_.value_or(WallClock::now()), zero_);
  timers_.push(Timer{base + ToWall(std::max(delay, SimTime::Zero())), id});
  timer_callbacks_.emplace(id, std::move(fn));
}

void LcmTransport::Authenticate(auth::MessageAuth auth) {
  auth_.emplace(std::move(auth));
  // Repeats are told after the tag, by the authenticated sender (udpm::Limits::drop_repeats).
  udpm::Limits limits = reassembler_.limits();
  limits.drop_repeats = false;
  reassembler_ = udpm::Reassembler(limits);
}

void LcmTransport::DoPublish(const std::string& channel, const char*, std::vector<std::uint8_t> bytes) {
  const std::size_t message = bytes.size();
  if (auth_) auth_->Seal(channel, bytes);
  Send(channel, bytes, message);
}

void LcmTransport::Send(const std::string& channel, const std::vector<std::uint8_t>& bytes, std::size_t message) {
  if (lcm_->publish(channel, bytes.data(), static_cast<unsigned>(bytes.size())) != 0) {
    ++publish_failures_;  // a full socket buffer: the message is lost, like a dropped packet
    return;
  }
  ++published_;
  published_bytes_ += bytes.size();
  // The observer sees the LCM message without its trailer (the wire model adds the trailer).
  if (on_publish_) on_publish_(channel, std::span<const std::uint8_t>(bytes.data(), message));
}

void LcmTransport::HoldUntilSubscribed(const std::vector<std::string>& channels, std::size_t max_bytes) {
  hold_limit_ = max_bytes;
  for (const std::string& channel : channels) {
    ChannelSubscription& sub = channels_[channel];
    sub.hold = sub.handlers.empty();
  }
}

std::uint64_t LcmTransport::DoSubscribe(const std::string& channel, RawHandler handler) {
  const std::uint64_t id = next_id_++;
  ChannelSubscription& sub = channels_[channel];
  sub.handlers.emplace(id, std::move(handler));
  channel_of_.emplace(id, channel);
  if (sub.hold) {
    sub.hold = false;
    if (!sub.held.empty()) {
      // Handled from the loop, not from inside Subscribe: the subscriber may not be ready yet.
      for (const Held& h : sub.held) held_bytes_ -= HeldCharge(h.bytes.size());
      ScheduleAfter(SimTime::Zero(), [this, channel, held = std::move(sub.held)] {
        for (const Held& h : held) Dispatch(channel, h.bytes, h.sender);
      });
      sub.held.clear();
    }
  }
  return id;
}

void LcmTransport::DoUnsubscribe(std::uint64_t id) {
  const auto it = channel_of_.find(id);
  if (it == channel_of_.end()) return;
  const auto sub = channels_.find(it->second);
  sub->second.handlers.erase(id);
  if (sub->second.handlers.empty()) channels_.erase(sub);
  channel_of_.erase(it);
}

void LcmTransport::ReceiveWaiting() {
  for (int n = 0; n < kDatagramsPerWait && !stopped_; ++n) {
    // A timer due now runs before the next datagram is read, as the simulation orders events by
    // time: a robot whose dropout is due does not answer a query that came after it, however
    // late its process was scheduled.
    if (!timers_.empty() && timers_.top().due <= WallClock::now()) return;
    const std::optional<udpm::Socket::Received> got = socket_.Receive(datagram_);
    if (!got) return;
    const std::span<const std::uint8_t> bytes(datagram_.data(), got->size);
    const std::optional<udpm::Message> message = reassembler_.Take(got->sender, bytes, WallClock::now());
    if (!message) continue;
    // Only the channels listened to reach Dispatch (LCM delivers only subscribed channels too).
    const auto sub = channels_.find(message->channel);
    if (sub == channels_.end()) continue;
    const std::string channel = sub->first;  // a copy: a handler may unsubscribe and erase the key
    if (!auth_) {
      Dispatch(channel, message->payload, message->sender.Key());
      continue;
    }
    const std::optional<auth::Opened> opened = auth_->Open(channel, message->payload);
    if (!opened) {
      ++auth_counts_.unauthenticated;
      continue;
    }
    if (!replay_.Take(opened->origin)) {
      ++auth_counts_.replayed;
      continue;
    }
    Dispatch(channel, opened->message, opened->origin.SenderKey());
  }
}

void LcmTransport::Dispatch(const std::string& channel, std::span<const std::uint8_t> bytes, std::uint64_t sender) {
  if (const auto held = channels_.find(channel); held != channels_.end() && held->second.hold) {
    const std::size_t charge = HeldCharge(bytes.size());
    if (held_bytes_ >= hold_limit_ || charge > hold_limit_ - held_bytes_) {
      ++auth_counts_.held_dropped;
      return;
    }
    held_bytes_ += charge;
    auth_counts_.held_bytes_peak = std::max(auth_counts_.held_bytes_peak, held_bytes_);
    held->second.held.push_back(Held{std::vector<std::uint8_t>(bytes.begin(), bytes.end()), sender});  // counted when handled
    return;
  }
  ++received_;
  if (on_receive_ && !on_receive_(channel, bytes, sender)) return;
  const auto sub = channels_.find(channel);
  if (sub == channels_.end()) return;
  // A handler may unsubscribe (itself or others): call copies, skip removed ones.
  std::vector<std::uint64_t> ids;
  for (const auto& [id, fn] : sub->second.handlers) ids.push_back(id);
  current_sender_ = sender;
  for (std::uint64_t id : ids) {
    const auto again = channels_.find(channel);
    if (again == channels_.end()) break;
    const auto h = again->second.handlers.find(id);
    if (h == again->second.handlers.end()) continue;
    RawHandler fn = h->second;
    fn(channel, bytes);
  }
  current_sender_ = 0;
}

void LcmTransport::RunDueTimers() {
  while (!timers_.empty() && !stopped_ && timers_.top().due <= WallClock::now()) {
    const Timer t = timers_.top();
    timers_.pop();
    auto it = timer_callbacks_.find(t.seq);
    Callback fn = std::move(it->second);
    timer_callbacks_.erase(it);
    running_due_ = t.due;
    try {
      fn();
    } catch (...) {
      running_due_.reset();
      throw;
    }
    running_due_.reset();
  }
}

// Waits up to `wait` for datagrams and handles what came.
void LcmTransport::WaitAndHandle(WallClock::duration wait) {
  const int fd = socket_.fd();
  const auto ns = std::chrono::duration_cast<std::chrono::nanoseconds>(std::max(wait, WallClock::duration::zero()));
  timespec timeout{static_cast<time_t>(ns.count() / 1000000000), static_cast<long>(ns.count() % 1000000000)};
  pollfd pfd{fd, POLLIN, 0};
  const int ready = ppoll(&pfd, 1, &timeout, nullptr);
  if (ready < 0) {
    if (errno == EINTR) return;
    throw std::runtime_error(std::string("LCM: poll failed: ") + std::strerror(errno));
  }
  if (ready > 0) ReceiveWaiting();
}

bool LcmTransport::RunUntilWall(WallClock::time_point deadline) {
  while (!stopped_) {
    RunDueTimers();
    if (stopped_) break;
    const auto now = WallClock::now();
    if (now >= deadline) return false;
    auto wait = deadline - now;
    if (!timers_.empty()) wait = std::min(wait, timers_.top().due - now);
    WaitAndHandle(wait);
  }
  return true;
}

bool LcmTransport::Run(SimTime deadline) {
  if (deadline == SimTime::Max()) return RunUntilWall(WallClock::time_point::max());
  return RunUntilWall(zero_ + ToWall(deadline));
}

}  // namespace dvpr
