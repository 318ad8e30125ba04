// wifi (802.11a DCF, wifi_link.h) against timelines worked by hand from the standard's constants
// and against Bianchi's saturation model. The numbers used throughout: a 544-byte query_t on
// "DVPR_QUERY_3" is a 593-byte IP packet and a 629-byte 802.11 frame (+ 24 MAC header, 8
// LLC/SNAP, 4 FCS). Its PPDU carries 16 + 629 x 8 + 6 = 5054 bits: at 54 Mbit/s (216 bits per
// 4 us symbol) 24 symbols, 20 + 96 = 116 us; at 6 Mbit/s (24 bits) 211 symbols, 20 + 844 = 864
// us. An ACK (14 bytes, 134 bits) at 6 Mbit/s: 6 symbols, 44 us; to a frame at 54 Mbit/s it goes
// at 24 Mbit/s (96 bits a symbol, as ns-3: the highest mandatory rate not above the data rate):
// 2 symbols, 28 us. Slot 9 us, SIFS 16, DIFS 34, EIFS 16 + 44 + 34 = 94 (the ACK at the basic
// rate); the ACK timeout SIFS + slot + 20 us of preamble and SIGNAL = 45 us.
#include "net_models/medium/wifi_link.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <iostream>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "net_models/mobility/fixed_mobility.h"
#include "net_models/network/network.h"
#include "net_models/propagation/full_mesh_propagation.h"
#include "net_models/propagation/range_propagation.h"
#include "sim/simulator.h"
#include "tests/net_models/copy_log.h"

namespace dvpr {
namespace {

TEST(WifiTiming, OfdmDurationsByHand) {
  EXPECT_EQ(OfdmDuration(Bytes(629), DataRate::Mbps(54)), SimTime::Micros(116));
  EXPECT_EQ(OfdmDuration(Bytes(629), DataRate::Mbps(6)), SimTime::Micros(864));
  EXPECT_EQ(OfdmDuration(Bytes(14), DataRate::Mbps(6)), SimTime::Micros(44));
  // 1500 bytes at 54 Mbit/s: 16 + 12000 + 6 = 12022 bits, 56 symbols: 244 us.
  EXPECT_EQ(OfdmDuration(Bytes(1500), DataRate::Mbps(54)), SimTime::Micros(244));
  EXPECT_EQ(WifiParams::kDifs, SimTime::Micros(34));
  EXPECT_EQ(Eifs(WifiParams{}), SimTime::Micros(94));
  EXPECT_EQ(OfdmDuration(Bytes(14), DataRate::Mbps(24)), SimTime::Micros(28));
  // ns-3's ACK rates (WifiRemoteStationManager::GetControlAnswerMode with 802.11a's mandatory
  // 6, 12 and 24 Mbit/s in the basic rate set).
  const auto ack = [](std::int64_t data_mbps) {
    WifiParams p;
    p.rate = DataRate::Mbps(data_mbps);
    return AckRate(p);
  };
  EXPECT_EQ(ack(6), DataRate::Mbps(6));
  EXPECT_EQ(ack(9), DataRate::Mbps(6));
  EXPECT_EQ(ack(18), DataRate::Mbps(12));
  EXPECT_EQ(ack(24), DataRate::Mbps(24));
  EXPECT_EQ(ack(54), DataRate::Mbps(24));
}

// Draws by station, in order; a station that runs out draws 0.
struct Draws {
  std::map<int, std::vector<std::uint32_t>> by_station;
  std::map<int, std::size_t> used;
  std::vector<std::pair<int, std::uint32_t>> calls;  // (station, cw) of each draw
  std::uint32_t operator()(int station, std::uint32_t cw) {
    calls.emplace_back(station, cw);
    const std::vector<std::uint32_t>& v = by_station[station];
    const std::size_t i = used[station]++;
    return i < v.size() ? v[i] : 0;
  }
};

struct Air {
  // Stations at `positions` (metres on a line), hearing each other within `range` (0: all).
  Air(std::vector<double> positions, double range, DataRate rate = DataRate::Mbps(54), int queue = 100) {
    const int n = static_cast<int>(positions.size());
    NetworkStack stack;
    std::vector<Position> at;
    for (const double x : positions) at.push_back(Position{x, 0, 0});
    stack.mobility = std::make_unique<FixedMobility>(std::move(at));
    if (range > 0) {
      stack.propagation = std::make_unique<RangePropagation>(*stack.mobility, range);
    } else {
      stack.propagation = std::make_unique<FullMeshPropagation>();
    }
    auto link = std::make_unique<WifiLink>(WifiParams{rate, DataRate::Mbps(6), queue}, n, 1);
    wifi = link.get();
    wifi->SetSlotDraw([this](int s, std::uint32_t cw) { return draws(s, cw); });
    stack.access = std::move(link);
    net = std::make_unique<Network>(sim, n, std::move(stack), LinkWire(WireParams{}, LinkFraming::kWifi));
    subscription = net->Subscribe(log);
    channel = net->InternChannel("DVPR_QUERY_3");
    type = net->InternType("dvpr.query_t");
  }
  void QueryAt(SimTime at, int src, std::vector<int> dsts, std::int64_t bytes = 544) {
    sim.ScheduleAt(at, [this, src, dsts, bytes] {
      std::vector<NodeId> to;
      for (const int d : dsts) to.push_back(NodeId(d));
      net->SendTo(NodeId(src), to, channel, type, std::vector<std::uint8_t>(static_cast<std::size_t>(bytes), 7));
    });
  }
  const MacCounters& Mac(int s) const { return net->link().Mac()[static_cast<std::size_t>(s)]; }

  Simulator sim;
  Draws draws;
  WifiLink* wifi = nullptr;
  std::unique_ptr<Network> net;
  testing_support::CopyLog log;
  ObserverSubscription subscription;
  ChannelId channel{};
  MessageTypeId type{};
};

TEST(WifiLink, OneUnicastFrameOnAnIdleMediumToTheNanosecond) {
  // Station 0's first backoff is 3 slots, counted from the start once the medium has been idle
  // DIFS: it transmits at 34 + 27 = 61 us; the frame ends (and arrives) at 61 + 116 = 177 us; the
  // ACK follows SIFS later, 193 to 221 us. Its next backoff, 2 slots, runs after DIFS from the
  // ACK's end: the second query goes at 221 + 34 + 18 = 273 us and arrives at 389 us.
  Air air({0, 10}, 0);
  air.draws.by_station[0] = {3, 2};
  air.QueryAt(SimTime::Zero(), 0, {1});
  air.QueryAt(SimTime::Zero(), 0, {1});
  air.sim.Run();
  EXPECT_EQ(air.log.lines, (std::vector<std::string>{"0>1 delivered at 177000ns", "0>1 delivered at 389000ns"}));
  EXPECT_EQ(air.Mac(0).attempts, 2u);
  EXPECT_EQ(air.Mac(0).retries, 0u);
  EXPECT_EQ(air.Mac(0).collisions, 0u);
  EXPECT_EQ(air.Mac(0).airtime, SimTime::Micros(232));
  // Busy: two frames and two ACKs.
  EXPECT_EQ(air.net->link().MediumBusy(), SimTime::Micros(2 * (116 + 28)));
  // Every draw in the first window: station 0's first; station 1's first, as the medium first
  // went busy for it (a draw at the start would count the same); station 0's after each frame.
  EXPECT_EQ(air.draws.calls, (std::vector<std::pair<int, std::uint32_t>>{{0, 15}, {1, 15}, {0, 15}, {0, 15}}));
}

// A frame for an empty queue whose backoff has run out (ns-3.37, ChannelAccessManager::
// NeedBackoffUponAccess): on an idle medium it goes DIFS after it arrived, not at once.
TEST(WifiLink, AFrameOnAnIdleMediumWithItsBackoffRunOutWaitsDifs) {
  // Station 0 drew 0 slots at the start; its query comes at 1 ms, the medium idle since 0: it
  // transmits at 1000 + 34 = 1034 us and the frame arrives at 1034 + 116 = 1150 us.
  Air air({0, 10}, 0);
  air.draws.by_station[0] = {0};
  air.QueryAt(SimTime::Millis(1), 0, {1});
  air.sim.Run();
  EXPECT_EQ(air.log.lines, (std::vector<std::string>{"0>1 delivered at 1150000ns"}));
}

// ... and on a busy medium it draws a new backoff instead of going DIFS after the medium is idle.
TEST(WifiLink, AFrameOnABusyMediumWithItsBackoffRunOutDrawsANewOne) {
  // Station 1's query at 0 (backoff 0) is on the air 34 to 150 us, its ACK 166 to 194 us.
  // Station 0's query comes at 100 us, its backoff 0 (drawn as the medium went busy at 34 us): it
  // draws again, 2 slots, and transmits at 194 + 34 + 18 = 246 us, arriving at 362 us (at
  // 228 + 116 = 344 us without the new draw).
  Air air({0, 10, 20}, 0);
  air.draws.by_station[0] = {0, 2};
  air.draws.by_station[1] = {0};
  air.QueryAt(SimTime::Zero(), 1, {2});
  air.QueryAt(SimTime::Micros(100), 0, {2});
  air.sim.Run();
  EXPECT_EQ(air.log.lines, (std::vector<std::string>{"1>2 delivered at 150000ns", "0>2 delivered at 362000ns"}));
  EXPECT_EQ(air.Mac(0).backoffs, 3u);  // the first, the new one, and the post-backoff after its frame
}

TEST(WifiLink, ABroadcastGoesAtTheBasicRateWithoutAck) {
  // A query for robots 1 and 2 is one frame at 6 Mbit/s: from 34 us (no backoff drawn) to 898 us.
  Air air({0, 10, 20}, 0);
  air.QueryAt(SimTime::Zero(), 0, {1, 2});
  air.sim.Run();
  EXPECT_EQ(air.log.lines, (std::vector<std::string>{"0>1 delivered at 898000ns", "0>2 delivered at 898000ns"}));
  EXPECT_EQ(air.Mac(0).attempts, 1u);
  EXPECT_EQ(air.net->link().MediumBusy(), SimTime::Micros(864));  // no ACK
}

TEST(WifiLink, ACollisionAndItsRetries) {
  // Stations 0 and 1 both draw 2 slots: both transmit at 34 + 18 = 52 us, and station 2 loses
  // both frames (to 168 us). No ACK: each times out at 168 + 45 = 213 us and doubles its window
  // to 31, drawing 1 (station 0) and 4 (station 1). Neither received the other's frame (each was
  // transmitting), so both wait DIFS: station 0 transmits at 213 + 34 + 9 = 256 us; station 1,
  // one slot counted by then, freezes with 3. Station 0's frame arrives at 372 us, its ACK runs
  // 388 to 416 us (station 1 defers to the NAV of the frame it overheard, and to the ACK); then
  // station 1 counts DIFS and 3 slots: 416 + 34 + 27 = 477 us, arriving at 593 us.
  Air air({0, 10, 20}, 0);
  air.draws.by_station[0] = {2, 1};
  air.draws.by_station[1] = {2, 4};
  air.QueryAt(SimTime::Zero(), 0, {2});
  air.QueryAt(SimTime::Zero(), 1, {2});
  air.sim.Run();
  EXPECT_EQ(air.log.lines, (std::vector<std::string>{"0>2 delivered at 372000ns", "1>2 delivered at 593000ns"}));
  for (const int s : {0, 1}) {
    EXPECT_EQ(air.Mac(s).attempts, 2u) << s;
    EXPECT_EQ(air.Mac(s).collisions, 1u) << s;
    EXPECT_EQ(air.Mac(s).retries, 1u) << s;
  }
  EXPECT_EQ(air.wifi->CorruptedAt(NodeId(2)), 2u);
  EXPECT_EQ(air.wifi->CorruptedAt(NodeId(0)), 0u);  // it was transmitting: it received nothing in error
  // Both windows doubled after the collision (the second draws had cw 31) and were reset after
  // each success (the post-backoff).
  std::map<int, std::vector<std::uint32_t>> windows;
  for (const auto& [station, cw] : air.draws.calls) windows[station].push_back(cw);
  EXPECT_EQ(windows[0], (std::vector<std::uint32_t>{15, 31, 15}));
  EXPECT_EQ(windows[1], (std::vector<std::uint32_t>{15, 31, 15}));
}

TEST(WifiLink, HiddenTerminalsCollideAtTheMiddleRobot) {
  // Robots at 0, 150 and 300 m, a 200 m range: 0 and 2 cannot hear each other. Both send to 1,
  // every backoff 0: each transmission starts DIFS after the last timeout, 116 + 45 + 34 = 195 us
  // apart, from 34 us; both collide at robot 1 all seven times, and both frames are given up at
  // the seventh timeout, 34 + 6 x 195 + 116 + 45 = 1365 us.
  Air air({0, 150, 300}, 200);
  air.QueryAt(SimTime::Zero(), 0, {1});
  air.QueryAt(SimTime::Zero(), 2, {1});
  air.sim.Run();
  EXPECT_EQ(air.log.lines,
            (std::vector<std::string>{"0>1 at 1365000ns: retry_limit", "2>1 at 1365000ns: retry_limit"}));
  EXPECT_EQ(air.wifi->CorruptedAt(NodeId(1)), 14u);
  for (const int s : {0, 2}) {
    EXPECT_EQ(air.Mac(s).attempts, 7u) << s;
    EXPECT_EQ(air.Mac(s).collisions, 7u) << s;
    EXPECT_EQ(air.Mac(s).retries, 6u) << s;
    EXPECT_EQ(air.Mac(s).dropped_retry_limit, 1u) << s;
  }
}

TEST(WifiLink, StationsThatHearEachOtherDeferInstead) {
  // The same three robots 10 m apart, and backoffs 0 and 1: robot 0 transmits at 34 us; robot 2
  // hears it and freezes with its one slot; after the ACK (166 to 194 us) it counts DIFS and the
  // slot: 194 + 34 + 9 = 237 us, arriving at 353 us. Nothing collides. Each arrival is 10 m of
  // air later: 33 ns.
  Air air({0, 10, 20}, 200);
  air.draws.by_station[2] = {1};
  air.QueryAt(SimTime::Zero(), 0, {1});
  air.QueryAt(SimTime::Zero(), 2, {1});
  air.sim.Run();
  EXPECT_EQ(air.log.lines, (std::vector<std::string>{"0>1 delivered at 150033ns", "2>1 delivered at 353033ns"}));
  EXPECT_EQ(air.wifi->CorruptedAt(NodeId(1)), 0u);
}

TEST(WifiLink, AUnicastToARobotOutOfRangeIsLostOutOfRange) {
  // Nobody at 500 m hears robot 0: seven unanswered transmissions, then out_of_range.
  Air air({0, 500}, 200);
  air.QueryAt(SimTime::Zero(), 0, {1});
  air.sim.Run();
  ASSERT_EQ(air.log.lines.size(), 1u);
  EXPECT_NE(air.log.lines[0].find("out_of_range"), std::string::npos) << air.log.lines[0];
  EXPECT_EQ(air.Mac(0).attempts, 7u);
}

// Bianchi (IEEE JSAC 18(3), 2000), basic access: tau, the probability a station transmits in a
// slot, and p, that its transmission collides, from the fixed point
//   tau = 2 (1 - 2p) / ((1 - 2p)(W + 1) + p W (1 - (2p)^m)),  p = 1 - (1 - tau)^(n - 1),
// W = CWmin + 1 = 16, m = 6 (CWmax + 1 = 2^6 W); successes per second
//   Ptr Ps / ((1 - Ptr) sigma + Ptr Ps Ts + Ptr (1 - Ps) Tc),
// Ptr = 1 - (1 - tau)^n, Ps = n tau (1 - tau)^(n - 1) / Ptr. Ts = data + SIFS + ACK + DIFS; after
// a collision the stations that heard it wait EIFS = SIFS + ACK + DIFS, so Tc = Ts too.
double BianchiSuccessesPerSecond(int n, double ts_us) {
  const double w = 16, m = 6, sigma = 9;
  const auto tau_of = [&](double p) {
    return 2 * (1 - 2 * p) / ((1 - 2 * p) * (w + 1) + p * w * (1 - std::pow(2 * p, m)));
  };
  double lo = 0, hi = 1;  // p - (1 - (1 - tau(p))^(n-1)) rises through 0 once in (0, 1)
  for (int i = 0; i < 200; ++i) {
    const double p = (lo + hi) / 2;
    const double f = p - (1 - std::pow(1 - tau_of(p), n - 1));
    (f < 0 ? lo : hi) = p;
  }
  const double tau = tau_of((lo + hi) / 2);
  const double ptr = 1 - std::pow(1 - tau, n);
  const double ps = n * tau * std::pow(1 - tau, n - 1) / ptr;
  const double slot_us = (1 - ptr) * sigma + ptr * ps * ts_us + ptr * (1 - ps) * ts_us;
  return ptr * ps / slot_us * 1e6;
}

TEST(WifiLink, SaturationThroughputIsBianchis) {
  // Always-backlogged stations, each sending 1500-byte frames to the next at 54 Mbit/s (a
  // 1415-byte payload on "DVPR_QUERY_3": 8 + 12 + 1 + 1415 + 28 = 1464 IP bytes, + 36), 3 s of
  // them. Data 244 us: Ts = 244 + SIFS 16 + the ACK at 24 Mbit/s 28 + DIFS 34 = 322 us (a
  // collision, 244 + the 45 us timeout + 34, is a microsecond longer: Bianchi's basic model takes
  // them equal).
  for (const int n : {2, 5, 10, 20}) {
    std::vector<double> line(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) line[static_cast<std::size_t>(i)] = i;
    Air air(line, 0, DataRate::Mbps(54), 1 << 20);
    air.wifi->SetSlotDraw({});  // the model's own random draws
    const int per_station = 12000 / n + 200;
    for (int s = 0; s < n; ++s) {
      for (int k = 0; k < per_station; ++k) air.QueryAt(SimTime::Zero(), s, {(s + 1) % n}, 1415);
    }
    const SimTime horizon = SimTime::Millis(3000);
    air.sim.Run(horizon);
    std::uint64_t delivered = 0;
    for (const std::string& line_text : air.log.lines) delivered += line_text.find("delivered") != std::string::npos;
    const double measured = static_cast<double>(delivered) / 3.0;
    const double bianchi = BianchiSuccessesPerSecond(n, 322);
    EXPECT_NEAR(measured / bianchi, 1.0, 0.05) << "n = " << n << ": " << measured << " vs " << bianchi;
    RecordProperty("frames_per_s_n" + std::to_string(n), std::to_string(measured) + " (Bianchi " +
                                                             std::to_string(bianchi) + ")");
    for (int s = 0; s < n; ++s) ASSERT_GT(air.net->link().Mac()[static_cast<std::size_t>(s)].attempts, 0u);
  }
}

}  // namespace
}  // namespace dvpr
