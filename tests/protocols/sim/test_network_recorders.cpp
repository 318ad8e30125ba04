// What a simulation records of its network through the network's hooks: the
// messages.csv rows (MessageRowRecorder) and the LCM event log
// (EventLogRecorder), on small networks with hand-worked times.
#include <gtest/gtest.h>
#include <lcm/eventlog.h>

#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "agents/messages/channels.h"
#include "agents/messages/sim_transport.h"
#include "experiments/protocols/sim/event_log_recorder.h"
#include "experiments/protocols/sim/message_rows.h"
#include "experiments/results/result_writers.h"
#include "net_models/medium/point_to_point_link.h"
#include "net_models/network/network.h"
#include "sim/simulator.h"

namespace dvpr {
namespace {

std::unique_ptr<LinkModel> Mbit1Links(int nodes) {
  return std::make_unique<PointToPointLink>(PointToPointParams{DataRate::Mbps(1), SimTime::Millis(5), 100, {}},
                                            nodes);
}

// Four nodes on 1 Mbit/s, 5 ms links, all on "ALL" (3 characters): a 505-byte
// payload is a 8 + 3 + 1 + 505 = 517-byte LCM datagram, a 547-byte frame,
// which arrives after 4.376 + 5 = 9.376 ms. Node 3 is offline: its copy is
// dropped at its arrival and has no delivery time.
TEST(MessageRowRecorder, OneRowPerMessageAndDestinationAsMessagesCsvWritesIt) {
  Simulator sim;
  Network net(sim, 4, Mbit1Links(4));
  const ChannelId all = net.InternChannel("ALL");
  for (int i = 0; i < 4; ++i) net.Join(NodeId(i), all);
  MessageRowRecorder recorder;
  const ObserverSubscription subscription = net.Subscribe(recorder);
  net.SetOffline(NodeId(3), SimTime::Zero());
  net.Send(NodeId(0), all, net.InternType("dvpr.test_t"), std::vector<std::uint8_t>(505, 7));
  sim.Run();
  std::vector<std::string> lines;
  for (MessageRow row : recorder.Rows()) {
    row.key = RunKey{.protocol = "sim", .strategy = "broadcast", .robots = 4, .run = 0, .network = {}};
    lines.push_back(CsvRow(row));
  }
  EXPECT_EQ(lines, (std::vector<std::string>{
                       "sim,broadcast,4,0,0,9376000,0,1,ALL,dvpr.test_t,505,547,0,,,,,,,other",  // ALL: no role of dvpr
                       "sim,broadcast,4,0,0,9376000,0,2,ALL,dvpr.test_t,505,547,0,,,,,,,other",
                       "sim,broadcast,4,0,0,,0,3,ALL,dvpr.test_t,505,547,1,,,,,,,other",
                   }));
}

// A recorder subscribed late keeps only the copies sent while subscribed,
// and a copy still in flight at the end has neither a delivery nor a drop.
TEST(MessageRowRecorder, CopiesSentBeforeTheSubscriptionAreNotRows) {
  Simulator sim;
  Network net(sim, 2, Mbit1Links(2));
  const ChannelId c = net.InternChannel("ALL");
  net.Join(NodeId(1), c);
  const MessageTypeId type = net.InternType("t");
  net.Send(NodeId(0), c, type, std::vector<std::uint8_t>(505));
  MessageRowRecorder recorder;
  const ObserverSubscription subscription = net.Subscribe(recorder);
  net.Send(NodeId(0), c, type, std::vector<std::uint8_t>(505));
  sim.Run(SimTime::Millis(10));  // the first arrives at 9.376 ms, the second at 13.752 ms
  const std::vector<MessageRow> in_flight = recorder.Rows();
  ASSERT_EQ(in_flight.size(), 1u);
  EXPECT_EQ(in_flight[0].sent_ns, 0);
  EXPECT_FALSE(in_flight[0].delivered_ns.has_value());
  EXPECT_FALSE(in_flight[0].dropped);
  sim.Run();
  EXPECT_EQ(recorder.Rows().at(0).delivered_ns, SimTime::Micros(13752).ns());
}

// Channel and type names are kept by the network's ids, which need not
// appear in order: here channel 1 and type 1 are sent first.
TEST(MessageRowRecorder, NamesComeBackWhateverOrderTheIdsAppearIn) {
  Simulator sim;
  Network net(sim, 2, Mbit1Links(2));
  const ChannelId a = net.InternChannel("A");
  const ChannelId b = net.InternChannel("B");
  const MessageTypeId s = net.InternType("s_t");
  const MessageTypeId t = net.InternType("t_t");
  MessageRowRecorder recorder;
  const ObserverSubscription subscription = net.Subscribe(recorder);
  const NodeId to1[] = {NodeId(1)};
  net.SendTo(NodeId(0), to1, b, t, std::vector<std::uint8_t>(1));
  net.SendTo(NodeId(0), to1, a, s, std::vector<std::uint8_t>(1));
  sim.Run();
  const std::vector<MessageRow> rows = recorder.Rows();
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].channel + " " + rows[0].type, "B t_t");
  EXPECT_EQ(rows[1].channel + " " + rows[1].type, "A s_t");
}

// Three robots on 1 Mbit/s, 5 ms links (as tests/agents/test_sim_transport.cpp):
//  query_t with 128 floats is 544 bytes; on "DVPR_QUERY_ALL" (14 chars): UDP
//  8 + 15 + 544 = 567, frame 597 bytes -> 4.776 ms + 5 ms = 9.776 ms.
//  match_t is 35 bytes; on "DVPR_MATCH_0" (12 chars): UDP 8 + 13 + 35 = 56,
//  frame 86 bytes -> 0.688 ms + 5 ms = 5.688 ms.
constexpr SimTime kQueryArrival = SimTime::Micros(9776);
constexpr SimTime kMatchArrival = SimTime::Micros(9776 + 5688);
// Virtual time 0 as a timestamp: 2011-10-03T12:00:00Z (python3: datetime(2011, 10, 3, 12,
// tzinfo=timezone.utc).timestamp() * 1e6).
constexpr std::int64_t kStartUtime = 1317643200000000;

query_t Query(int robot, int frame) {
  query_t q{};
  q.robot = static_cast<std::int16_t>(robot);
  q.frame = frame;
  q.dim = 128;
  q.descriptor.assign(128, 0.25f);
  return q;
}

// Robot 0 broadcasts a query, robots 1 and 2 answer it: the log holds the
// query once (not once per receiver) and both matches, at their first
// delivery, stamped with the run's start instant + virtual time, and each
// event decodes into its type.
TEST(EventLogRecorder, LogsEachMessageOnceAtItsFirstDelivery) {
  const std::filesystem::path path = std::filesystem::path(DVPR_TEST_TMP) / "event_log_recorder.lcmlog";
  std::filesystem::create_directories(path.parent_path());
  {
    Simulator sim;
    Network net(sim, 3, Mbit1Links(3));
    std::vector<std::unique_ptr<SimTransport>> robots;
    for (int r = 0; r < 3; ++r) robots.push_back(std::make_unique<SimTransport>(net, NodeId(r)));
    std::vector<Subscription> subs;
    for (int r = 1; r < 3; ++r) {
      SimTransport* t = robots[static_cast<std::size_t>(r)].get();
      subs.push_back(t->Subscribe<query_t>(channels::kQueryAll, [t, r](const query_t& q) {
        match_t m{};
        m.query_robot = q.robot;
        m.query_frame = q.frame;
        m.responder = static_cast<std::int16_t>(r);
        t->Publish(channels::Match(RobotId(q.robot)), m);
      }));
    }
    subs.push_back(robots[0]->Subscribe<match_t>(channels::Match(RobotId(0)), [](const match_t&) {}));
    LcmEventLogWriter writer(path);
    EventLogRecorder recorder(writer, kStartUtime);
    const ObserverSubscription subscription = net.Subscribe(recorder);
    robots[0]->Publish(channels::kQueryAll, Query(0, 17));
    sim.Run();
    EXPECT_EQ(writer.EventsWritten(), 3);
  }
  lcm_eventlog_t* log = lcm_eventlog_create(path.c_str(), "r");
  ASSERT_NE(log, nullptr);
  std::vector<std::pair<std::string, std::int64_t>> seen;
  int queries = 0, matches = 0;
  while (lcm_eventlog_event_t* e = lcm_eventlog_read_next_event(log)) {
    const std::string channel(e->channel, static_cast<std::size_t>(e->channellen));
    const std::span<const std::uint8_t> data(static_cast<const std::uint8_t*>(e->data),
                                             static_cast<std::size_t>(e->datalen));
    seen.emplace_back(channel, e->timestamp);
    if (channel == channels::kQueryAll) {
      const auto q = Decode<query_t>(data);
      ASSERT_TRUE(q.has_value());
      EXPECT_EQ(q->frame, 17);
      ++queries;
    } else {
      const auto m = Decode<match_t>(data);
      ASSERT_TRUE(m.has_value()) << channel;
      EXPECT_EQ(m->query_frame, 17);
      ++matches;
    }
    lcm_eventlog_free_event(e);
  }
  lcm_eventlog_destroy(log);
  EXPECT_EQ(queries, 1);
  EXPECT_EQ(matches, 2);
  ASSERT_EQ(seen.size(), 3u);
  EXPECT_EQ(seen[0], std::make_pair(std::string("DVPR_QUERY_ALL"), kStartUtime + 9776));
  EXPECT_EQ(seen[1], std::make_pair(std::string("DVPR_MATCH_0"), kStartUtime + 9776 + 5688));
  EXPECT_EQ(seen[2], std::make_pair(std::string("DVPR_MATCH_0"), kStartUtime + 9776 + 5688));
}

}  // namespace
}  // namespace dvpr
