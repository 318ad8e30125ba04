#include "agents/udpm/udpm_reassembler.h"

#include <algorithm>
#include <iterator>
#include <stdexcept>
#include <string>

namespace dvpr::udpm {

namespace {

// What a kept fragment and a partial message cost beyond their bytes (map and set nodes,
// vector headers), charged against Limits::max_partial_bytes so that a flood of 1-byte
// fragments cannot hold more memory than the limit says.
constexpr std::size_t kFragmentOverhead = 128;
constexpr std::size_t kPartialOverhead = 256;
constexpr std::uint16_t kMostFragments = 65535;
constexpr auto kSweepPeriod = std::chrono::milliseconds(100);

}  // namespace

void Limits::Validate() const {
  auto fail = [](const std::string& what) { throw std::invalid_argument("udpm limits: " + what); };
  if (max_message_bytes < 1 || max_message_bytes > kMaxMessageBytes) {
    fail("max_message_bytes must be in [1, 2^28], got " + std::to_string(max_message_bytes));
  }
  const std::size_t largest = std::size_t{max_message_bytes} + kMostFragments * kFragmentOverhead + kPartialOverhead;
  if (max_partial_bytes < largest) {
    fail("max_partial_bytes must hold the largest message with its bookkeeping (" + std::to_string(largest) +
         " bytes), got " + std::to_string(max_partial_bytes));
  }
  if (partials_per_sender < 1) fail("partials_per_sender must be at least 1");
  if (max_senders < 1) fail("max_senders must be at least 1");
  if (partial_timeout <= Clock::duration::zero()) fail("partial_timeout must be positive");
}

bool Reassembler::SeqnoWindow::Seen(std::uint32_t seqno) const {
  if (!any_) return false;
  const std::uint32_t age = newest_ - seqno;  // wraps: a number ahead of newest_ is "very old"
  if (age >= kSpan) return false;
  return (bits_[age / 64] >> (age % 64)) & 1u;
}

void Reassembler::SeqnoWindow::Mark(std::uint32_t seqno) {
  if (!any_) {
    any_ = true;
    newest_ = seqno;
    bits_.fill(0);
    bits_[0] = 1;
    return;
  }
  const std::uint32_t age = newest_ - seqno;
  if (age < kSpan) {
    bits_[age / 64] |= std::uint64_t{1} << (age % 64);
    return;
  }
  const std::uint32_t ahead = seqno - newest_;
  if (ahead >= 0x80000000u) return;  // far behind (a restarted sender): taken, not remembered
  // Every remembered number gets `ahead` older.
  std::array<std::uint64_t, kSpan / 64> moved{};
  if (ahead < kSpan) {
    const std::size_t words = ahead / 64, shift = ahead % 64;
    for (std::size_t i = words; i < moved.size(); ++i) {
      moved[i] = bits_[i - words] << shift;
      if (shift != 0 && i > words) moved[i] |= bits_[i - words - 1] >> (64 - shift);
    }
  }
  bits_ = moved;
  bits_[0] |= 1u;
  newest_ = seqno;
}

Reassembler::Reassembler(Limits limits) : limits_(limits) { limits_.Validate(); }

std::size_t Reassembler::partial_messages() const {
  std::size_t n = 0;
  for (const auto& [key, state] : senders_) n += state.partials.size();
  return n;
}

std::optional<Message> Reassembler::Take(const Sender& sender, std::span<const std::uint8_t> datagram,
                                         Clock::time_point now) {
  ++counts_.datagrams;
  DropStale(now);
  const Datagram d = ParseDatagram(datagram);
  if (d.kind == DatagramKind::kMalformed ||
      (d.kind == DatagramKind::kFragment && d.message_size > limits_.max_message_bytes)) {
    ++counts_.malformed;
    return std::nullopt;
  }
  SenderState& state = StateOf(sender, now);
  if (limits_.drop_repeats && state.taken.Seen(d.seqno)) {
    ++counts_.duplicates;
    return std::nullopt;
  }
  if (d.kind == DatagramKind::kFragment) return TakeFragment(sender, state, d, now);
  state.taken.Mark(d.seqno);
  ++counts_.messages;
  return Message{d.channel, d.bytes, sender, d.seqno};
}

Reassembler::SenderState& Reassembler::StateOf(const Sender& sender, Clock::time_point now) {
  auto it = senders_.find(sender.Key());
  if (it == senders_.end()) {
    if (senders_.size() >= static_cast<std::size_t>(limits_.max_senders)) {
      auto oldest = std::min_element(senders_.begin(), senders_.end(), [](const auto& a, const auto& b) {
        return a.second.last_heard < b.second.last_heard;
      });
      while (!oldest->second.partials.empty()) Drop(oldest->second, oldest->second.partials.begin(), true);
      senders_.erase(oldest);
    }
    it = senders_.emplace(sender.Key(), SenderState{}).first;
  }
  it->second.last_heard = now;
  return it->second;
}

std::optional<Message> Reassembler::TakeFragment(const Sender& sender, SenderState& state, const Datagram& d,
                                                 Clock::time_point now) {
  auto p = std::find_if(state.partials.begin(), state.partials.end(),
                        [&](const Partial& q) { return q.seqno == d.seqno; });
  if (p == state.partials.end()) {
    if (state.partials.size() >= static_cast<std::size_t>(limits_.partials_per_sender)) {
      Drop(state, std::min_element(state.partials.begin(), state.partials.end(),
                                   [](const Partial& a, const Partial& b) { return a.last < b.last; }),
           true);
    }
    Partial fresh;
    fresh.seqno = d.seqno;
    fresh.message_size = d.message_size;
    fresh.fragments = d.fragments;
    fresh.charge = kPartialOverhead;
    fresh.last = now;
    partial_bytes_ += fresh.charge;
    p = state.partials.insert(state.partials.end(), std::move(fresh));
  }
  switch (Add(*p, d, now)) {
    case Added::kYes: break;
    case Added::kDuplicate: ++counts_.duplicates; return std::nullopt;
    case Added::kDisagrees: ++counts_.malformed; return std::nullopt;
  }
  if (p->numbers.size() < p->fragments) return std::nullopt;
  // Every fragment number is in; without overlaps, within the message, the bytes tile it
  // exactly when they add up to its size.
  if (p->kept != p->message_size) {
    ++counts_.malformed;
    Drop(state, p, true);
    return std::nullopt;
  }
  completed_.resize(p->message_size);
  for (const auto& [offset, bytes] : p->by_offset) std::copy(bytes.begin(), bytes.end(), completed_.begin() + offset);
  completed_channel_ = std::move(p->channel);
  const std::uint32_t seqno = p->seqno;
  Drop(state, p, false);
  state.taken.Mark(seqno);
  ++counts_.messages;
  return Message{completed_channel_, completed_, sender, seqno};
}

Reassembler::Added Reassembler::Add(Partial& p, const Datagram& d, Clock::time_point now) {
  if (p.message_size != d.message_size || p.fragments != d.fragments) return Added::kDisagrees;
  if (p.numbers.count(d.fragment_no) != 0) return Added::kDuplicate;
  const std::uint64_t end = std::uint64_t{d.offset} + d.bytes.size();  // <= message_size: checked in parsing
  const auto next = p.by_offset.lower_bound(d.offset);
  if (next != p.by_offset.end() && next->first < end) return Added::kDisagrees;  // overlaps the next one
  if (next != p.by_offset.begin()) {
    const auto prev = std::prev(next);
    if (prev->first + prev->second.size() > d.offset) return Added::kDisagrees;  // overlaps the one before
  }
  const std::size_t charge = d.bytes.size() + kFragmentOverhead;
  MakeRoom(charge, &p);
  p.by_offset.emplace(d.offset, std::vector<std::uint8_t>(d.bytes.begin(), d.bytes.end()));
  p.numbers.insert(d.fragment_no);
  if (d.fragment_no == 0) p.channel = std::string(d.channel);
  p.kept += d.bytes.size();
  p.charge += charge;
  partial_bytes_ += charge;
  p.last = now;
  return Added::kYes;
}

// Drops the least recently extended partial messages (never `keep`) until `bytes` more fit.
void Reassembler::MakeRoom(std::size_t bytes, const Partial* keep) {
  while (partial_bytes_ + bytes > limits_.max_partial_bytes) {
    SenderState* owner = nullptr;
    std::list<Partial>::iterator oldest;
    for (auto& [key, state] : senders_) {
      for (auto it = state.partials.begin(); it != state.partials.end(); ++it) {
        if (&*it == keep) continue;
        if (owner == nullptr || it->last < oldest->last) {
          owner = &state;
          oldest = it;
        }
      }
    }
    if (owner == nullptr) return;  // only `keep` is left, and Validate made room for it
    Drop(*owner, oldest, true);
  }
}

void Reassembler::DropStale(Clock::time_point now) {
  if (now < next_sweep_) return;
  next_sweep_ = now + kSweepPeriod;
  for (auto& [key, state] : senders_) {
    for (auto it = state.partials.begin(); it != state.partials.end();) {
      const auto next = std::next(it);
      if (now - it->last > limits_.partial_timeout) Drop(state, it, true);
      it = next;
    }
  }
}

void Reassembler::Drop(SenderState& state, std::list<Partial>::iterator partial, bool lost) {
  partial_bytes_ -= partial->charge;
  if (lost) ++counts_.incomplete;
  state.partials.erase(partial);
}

}  // namespace dvpr::udpm
