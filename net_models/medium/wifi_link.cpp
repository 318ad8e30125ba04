#include "net_models/medium/wifi_link.h"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>

#include "net_models/core/param_checks.h"

namespace dvpr {
namespace {

constexpr std::array<std::int64_t, 8> kOfdmMbps = {6, 9, 12, 18, 24, 36, 48, 54};

std::string OfdmRates() {
  std::string out;
  for (const std::int64_t m : kOfdmMbps) out += (out.empty() ? "" : ", ") + std::to_string(m);
  return out + " Mbit/s";
}

}  // namespace

bool IsOfdmRate(DataRate rate) {
  return std::any_of(kOfdmMbps.begin(), kOfdmMbps.end(), [&](std::int64_t m) { return rate == DataRate::Mbps(m); });
}

SimTime OfdmDuration(Bytes bytes, DataRate rate) {
  if (!IsOfdmRate(rate)) throw std::logic_error("OfdmDuration: not an 802.11a rate");
  const std::int64_t bits_per_symbol = rate.bps() / 250000;  // N_DBPS: 4 us symbols, 24 bits at 6 Mbit/s
  const std::int64_t bits = WifiParams::kServiceBits + 8 * bytes.value() + WifiParams::kTailBits;
  const std::int64_t symbols = (bits + bits_per_symbol - 1) / bits_per_symbol;
  return WifiParams::kPreamble + WifiParams::kSignal + WifiParams::kSymbol * symbols;
}

SimTime Eifs(const WifiParams& params) {
  return WifiParams::kSifs + OfdmDuration(WifiParams::kAck, params.basic_rate) + WifiParams::kDifs;
}

DataRate AckRate(const WifiParams& params) {
  DataRate mandatory = DataRate::Mbps(6);
  for (const std::int64_t m : {12, 24}) {
    if (DataRate::Mbps(m) <= params.rate) mandatory = DataRate::Mbps(m);
  }
  return std::max(mandatory, params.basic_rate);
}

void WifiParams::Validate() const {
  if (rate == DataRate()) InvalidParam("rate", "model wifi needs a data rate: one of " + OfdmRates());
  if (!IsOfdmRate(rate)) InvalidParam("rate", "must be an 802.11a rate (" + OfdmRates() + "), got " + ToString(rate));
  if (!IsOfdmRate(basic_rate)) {
    InvalidParam("basic_rate", "must be an 802.11a rate (" + OfdmRates() + "), got " + ToString(basic_rate));
  }
  CheckInRange("queue_packets", queue_packets, 1, std::int64_t{1} << 30);
}

WifiLink::WifiLink(const WifiParams& params, int nodes, std::uint64_t run_seed) : params_(params) {
  if (nodes <= 0) InvalidParam("nodes", "a network needs at least one node, got " + std::to_string(nodes));
  params_.Validate();
  eifs_ = Eifs(params_);
  ack_rate_ = AckRate(params_);
  ack_time_ = OfdmDuration(WifiParams::kAck, ack_rate_);
  stations_.reserve(static_cast<std::size_t>(nodes));
  for (int s = 0; s < nodes; ++s) {
    stations_.emplace_back(RandomStream(run_seed, ComponentId("wifi/backoff/" + std::to_string(s))));
  }
  counters_.assign(static_cast<std::size_t>(nodes), MacCounters{});
  corrupted_.assign(static_cast<std::size_t>(nodes), 0);
}

void WifiLink::DoBind(Simulator& sim, TransmissionLedger& ledger) {
  sim_ = &sim;
  messages_ = &ledger;
}

LinkModel::MediumUse WifiLink::DoTransmit(const LinkTransmission& t, std::span<LinkDelivery> out) {
  if (sim_ == nullptr) throw std::logic_error("WifiLink: Transmit before Bind (wifi runs on a network's simulator)");
  const auto s = static_cast<std::size_t>(t.src.value);
  Station& st = stations_[s];
  MediumUse use{t.dsts.empty() ? 0u : 1u, Bytes(0)};
  const std::uint32_t id =
      messages_->Enqueue(t, st.queue, static_cast<std::size_t>(params_.queue_packets), counters_[s], use, [] {});
  if (st.phase == Phase::kIdle && !st.queue.empty()) {
    EnsureDrawn(s);
    // A frame for an empty queue whose backoff has run out (ns-3.37's
    // ChannelAccessManager::NeedBackoffUponAccess): on an idle medium it goes DIFS after it
    // arrived if the medium stays idle; on a busy one it draws a new backoff.
    if (st.busy) {
      if (st.slots == 0) st.slots = Draw(s);
    } else if (SlotsLeft(st) == 0) {
      st.not_before = sim_->Now() + WifiParams::kDifs;
    }
    st.current = st.queue.front();
    st.queue.pop_front();
    st.phase = Phase::kContend;
    if (!st.busy) ScheduleAccess(s);
  }
  messages_->HandOver(id, out, use);
  return use;
}

// As ns-3 draws a backoff when a station starts: the first is drawn when first needed, which
// gives the same count as a draw at the start (the draws do not depend on the time).
void WifiLink::EnsureDrawn(std::size_t s) {
  Station& st = stations_[s];
  if (st.drawn) return;
  st.slots = Draw(s);
  st.drawn = true;
}

std::uint32_t WifiLink::Draw(std::size_t s) {
  Station& st = stations_[s];
  ++counters_[s].backoffs;
  if (draw_) {
    const std::uint32_t slots = draw_(static_cast<int>(s), st.cw);
    if (slots > st.cw) throw std::logic_error("WifiLink: a drawn backoff outside [0, cw]");
    return slots;
  }
  return static_cast<std::uint32_t>(st.rng.UniformInt(std::uint64_t{st.cw} + 1));
}

std::uint32_t WifiLink::SlotsLeft(const Station& st) const {
  const SimTime start = st.idle_since + Ifs(st);
  const SimTime now = sim_->Now();
  if (now <= start) return st.slots;
  const auto counted = static_cast<std::uint64_t>((now - start).ns() / WifiParams::kSlot.ns());
  return counted >= st.slots ? 0 : st.slots - static_cast<std::uint32_t>(counted);
}

void WifiLink::Reassess(std::size_t s) {
  Station& st = stations_[s];
  const SimTime now = sim_->Now();
  const bool busy = st.heard > 0 || st.tx_on || st.phase == Phase::kAwaitAck || now < st.nav_until;
  if (busy == st.busy) return;
  if (busy) {
    EnsureDrawn(s);
    st.slots = SlotsLeft(st);
    st.busy = true;
    // An access due now still happens: its slot ended as the medium went busy (a collision).
    if (st.attempt.IsValid() && st.access_at > now) {
      sim_->Cancel(st.attempt);
      st.attempt = EventId();
    }
    return;
  }
  st.busy = false;
  st.idle_since = now;
  if (st.phase == Phase::kContend) ScheduleAccess(s);
}

void WifiLink::ScheduleAccess(std::size_t s) {
  Station& st = stations_[s];
  if (st.attempt.IsValid()) return;  // due now, from before the medium went busy
  st.access_at = std::max({sim_->Now(), st.idle_since + Ifs(st) + WifiParams::kSlot * st.slots, st.not_before});
  st.attempt = sim_->ScheduleAt(st.access_at, [this, s] { Access(s); });
}

void WifiLink::Access(std::size_t s) {
  Station& st = stations_[s];
  st.attempt = EventId();
  if (st.phase != Phase::kContend) throw std::logic_error("WifiLink: access without a frame");
  const std::uint32_t message = st.current.message;
  const std::span<const NodeId> dsts = messages_->Destinations(message);
  Air what;
  what.src = s;
  what.broadcast = dsts.size() != 1;
  what.message = message;
  what.to = what.broadcast ? 0 : static_cast<std::size_t>(dsts.front().value);
  const DataRate rate = what.broadcast ? params_.basic_rate : params_.rate;
  st.phase = Phase::kTransmit;
  st.tx_on = true;
  ++st.transmissions;
  MacCounters& c = counters_[s];
  ++c.attempts;
  if (st.transmissions > 1) ++c.retries;
  c.airtime += OfdmDuration(st.current.size, rate);
  Reassess(s);
  StartAir(s, st.current.size, rate, what);
}

void WifiLink::Corrupt(std::uint32_t air, std::size_t station, char how) {
  Air& a = air_[air];
  for (std::size_t k = 0; k < a.hearers.size(); ++k) {
    if (a.hearers[k] == station && a.corrupted[k] == kClean) a.corrupted[k] = how;
  }
}

// Puts a transmission on the air: every station in range hears it until it ends; one that
// already hears another, or transmits, loses both.
void WifiLink::StartAir(std::size_t src, Bytes bytes, DataRate rate, const Air& what) {
  const SimTime now = sim_->Now();
  const std::uint32_t id = air_.Acquire();
  // Half duplex: what the sender was receiving is lost to it.
  for (const std::uint32_t other : stations_[src].hearing) Corrupt(other, src, kUnheard);
  others_.clear();
  for (std::size_t n = 0; n < stations_.size(); ++n) {
    if (n != src) others_.push_back(NodeId(static_cast<int>(n)));
  }
  reach_.resize(others_.size());
  Hear(NodeId(static_cast<int>(src)), others_, now, reach_);
  Air& a = air_[id];
  a = what;
  a.hearers.clear();
  a.corrupted.clear();
  a.delay.clear();
  for (std::size_t i = 0; i < others_.size(); ++i) {
    if (!reach_[i].reaches) continue;
    const auto h = static_cast<std::size_t>(others_[i].value);
    Station& hs = stations_[h];
    for (const std::uint32_t other : hs.hearing) Corrupt(other, h, kCollided);
    a.hearers.push_back(h);
    a.corrupted.push_back(hs.tx_on ? kUnheard : hs.hearing.empty() ? kClean : kCollided);
    a.delay.push_back(reach_[i].delay);
    hs.hearing.push_back(id);
    ++hs.heard;
    if (!a.ack && !a.broadcast && h == a.to) stations_[src].dst_heard = true;
  }
  if (on_air_++ == 0) on_air_since_ = now;
  sim_->Schedule(OfdmDuration(bytes, rate), [this, id] { EndAir(id); });
  for (const std::size_t h : air_[id].hearers) Reassess(h);
}

void WifiLink::EndAir(std::uint32_t id) {
  const SimTime now = sim_->Now();
  if (--on_air_ == 0) medium_busy_ += now - on_air_since_;
  const Air a = std::move(air_[id]);  // moved out: what follows may put new transmissions on the air
  air_.Release(id);
  stations_[a.src].tx_on = false;
  bool acked = false;
  bool ack_lost = false;
  const std::span<const NodeId> dsts = a.ack ? std::span<const NodeId>() : messages_->Destinations(a.message);
  std::vector<char>& reached = reached_;  // by destination: 0 not heard, 1 received, 2 lost to a collision
  reached.assign(dsts.size(), 0);
  bool collided = false;  // lost at a receiver it was for (counted once per transmission)
  for (std::size_t k = 0; k < a.hearers.size(); ++k) {
    const std::size_t h = a.hearers[k];
    Station& hs = stations_[h];
    hs.hearing.erase(std::find(hs.hearing.begin(), hs.hearing.end(), id));
    --hs.heard;
    const bool ok = a.corrupted[k] == kClean;
    // A frame received in error sets EIFS; one that came while the station transmitted was never
    // received at all (its radio was busy sending), and changes nothing.
    if (a.corrupted[k] != kUnheard) hs.eifs = !ok;
    if (a.corrupted[k] == kCollided) ++corrupted_[h];
    if (a.ack) {
      if (h == a.to) (ok ? acked : ack_lost) = true;
      continue;
    }
    if (a.broadcast) {
      const std::size_t i = IndexOf(a.message, h);
      if (i == dsts.size()) continue;
      collided = collided || !ok;
      if (ok) {
        messages_->Reached(a.message, i, now + a.delay[k]);
        reached[i] = 1;
      } else {
        messages_->Lost(a.message, i, DropReason::kCollision);
        reached[i] = 2;
      }
      continue;
    }
    if (h == a.to) {
      collided = collided || !ok;
      if (!ok) continue;
      Station& sender = stations_[a.src];
      if (!sender.settled) {  // a retransmission after a lost ACK arrives twice: the first counts
        sender.settled = true;
        messages_->Reached(a.message, 0, now + a.delay[k]);
        messages_->Settle(a.message);
      }
      sim_->Schedule(WifiParams::kSifs, [this, h, src = a.src] { SendAck(h, src); });
    } else if (ok) {
      // The overheard frame's duration field covers SIFS and its ACK (virtual carrier sense).
      const SimTime nav = now + WifiParams::kSifs + ack_time_;
      if (nav > hs.nav_until) {
        hs.nav_until = nav;
        sim_->ScheduleAt(nav, [this, h] { Reassess(h); });
      }
    }
  }
  if (collided) ++counters_[a.src].collisions;
  if (a.ack) {
    Station& target = stations_[a.to];
    if (target.phase == Phase::kAwaitAck) {
      if (acked) {
        NextFrame(a.to);
      } else if (ack_lost && now >= target.ack_deadline) {
        Failed(a.to);
      }
    }
  } else if (a.broadcast) {
    for (std::size_t i = 0; i < dsts.size(); ++i) {
      if (reached[i] == 0) messages_->Lost(a.message, i, DropReason::kOutOfRange);
    }
    messages_->Settle(a.message);
    NextFrame(a.src);
  } else {
    Station& st = stations_[a.src];
    st.phase = Phase::kAwaitAck;
    const std::uint64_t token = ++st.ack_token;
    st.ack_deadline = now + WifiParams::kSifs + WifiParams::kSlot + WifiParams::kPreamble + WifiParams::kSignal;
    sim_->ScheduleAt(st.ack_deadline, [this, s = a.src, token] { AckTimeout(s, token); });
  }
  for (const std::size_t h : a.hearers) Reassess(h);
  Reassess(a.src);
}

void WifiLink::SendAck(std::size_t from, std::size_t to) {
  Station& st = stations_[from];
  if (st.tx_on) return;  // it has started a transmission of its own meanwhile
  Air what;
  what.src = from;
  what.ack = true;
  what.to = to;
  st.tx_on = true;
  Reassess(from);
  StartAir(from, WifiParams::kAck, ack_rate_, what);
}

// No ACK has begun by the timeout (ns-3: SIFS + a slot + the ACK's preamble and SIGNAL): the
// attempt failed. One that has begun decides when it ends (EndAir).
void WifiLink::AckTimeout(std::size_t s, std::uint64_t token) {
  Station& st = stations_[s];
  if (st.phase != Phase::kAwaitAck || st.ack_token != token) return;
  for (const std::uint32_t id : st.hearing) {
    if (air_[id].ack && air_[id].to == s) return;
  }
  Failed(s);
}

void WifiLink::Failed(std::size_t s) {
  Station& st = stations_[s];
  if (st.transmissions >= WifiParams::kMaxTransmissions) {
    ++counters_[s].dropped_retry_limit;
    if (!st.settled) {
      // Never heard by its receiver: out of range; heard but never received: given up.
      messages_->Lost(st.current.message, 0, st.dst_heard ? DropReason::kRetryLimit : DropReason::kOutOfRange);
      st.settled = true;
      messages_->Settle(st.current.message);
    }
    NextFrame(s);
    return;
  }
  st.cw = std::min(2 * st.cw + 1, WifiParams::kCwMax);
  st.slots = Draw(s);
  st.phase = Phase::kContend;
  Reassess(s);
  if (!st.busy) ScheduleAccess(s);
}

// The frame is done (acknowledged, broadcast, or given up): a fresh window and a new backoff,
// counted down even without a frame (the post-backoff), and the next frame if there is one.
void WifiLink::NextFrame(std::size_t s) {
  Station& st = stations_[s];
  ++st.ack_token;  // a pending timeout is stale
  st.cw = WifiParams::kCwMin;
  st.slots = Draw(s);
  st.not_before = SimTime::Zero();
  st.transmissions = 0;
  st.settled = false;
  st.dst_heard = false;
  if (st.queue.empty()) {
    st.phase = Phase::kIdle;
  } else {
    st.current = st.queue.front();
    st.queue.pop_front();
    st.phase = Phase::kContend;
  }
  Reassess(s);
  if (!st.busy && st.phase == Phase::kContend) ScheduleAccess(s);
}

std::size_t WifiLink::IndexOf(std::uint32_t message, std::size_t station) const {
  const std::span<const NodeId> dsts = messages_->Destinations(message);
  for (std::size_t i = 0; i < dsts.size(); ++i) {
    if (static_cast<std::size_t>(dsts[i].value) == station) return i;
  }
  return dsts.size();
}

}  // namespace dvpr
