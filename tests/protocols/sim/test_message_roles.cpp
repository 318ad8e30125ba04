// Bytes by message role (issue 16): RoleBytesRecorder on a hand-worked three-robot exchange, with
// every size worked out from LCM's encoding rules and docs/design.md section 4
// (net_models/core/wire_format.h), not taken from the code under test. The role of every channel is
// pinned in tests/agents/recluster/test_every_channel.cpp.
//
// Depends on the LCM sizes of query_t, match_t, verify_request_t, verify_result_t and
// centroid_table_t: a field added to one of them changes the numbers below (each is derived in
// a comment so it can be updated by hand).
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "agents/messages/channels.h"
#include "agents/messages/lcm_codec.h"
#include "agents/recluster/recluster_messages.h"
#include "experiments/protocols/sim/message_roles.h"
#include "net_models/medium/shared_medium_link.h"
#include "net_models/network/network.h"
#include "sim/simulator.h"

namespace dvpr {
namespace {

constexpr std::size_t Role(MessageRole r) { return static_cast<std::size_t>(r); }

// Three robots on one shared medium (1 Gbit/s, 1 ms), robot 2 offline from the start. Robot 0
// queries robot 1 (the paper's method), then all (broadcast), verifies with robot 1 and sends a
// re-clustering table to both; robots 1 and 2 reply. d = 128.
//
// LCM payloads (8-byte fingerprint included):
//   query_t          8 + utime 8 + robot 2 + frame 4 + capture_utime 8 + dim 2 + 128 x 4 = 544
//   match_t          8 + 8 + 2 + 4 + responder 2 + has_match 1 + 2 + 4 + 4  =    35
//   verify_request_t 8 + 8 + 2 + 4 + 2 + 4 + payload_size 4 + 25000         = 25032
//   verify_result_t  8 + 8 + 2 + 4 + 2 + 4 + accepted 1 + inliers 4         =    33
//   centroid_table_t 8 + 8 + epoch 4 + leader 2 + k 2 + dim 2 + 3 x (512 + 2) = 1568
// Link frames: LCM 8 + channel + NUL + payload, + UDP 8 + IPv4 20 (fragments of 1480 data bytes
// at MTU 1500, 20 bytes of IP header each), + PPP 2 per IP packet:
//   query on DVPR_QUERY_1 (12):   8 + 12 + 1 + 544 = 565; + 28 = 593; + 2            =   595
//   query on DVPR_QUERY_ALL (14): 567; 595; 597                                       =   597
//   match on DVPR_MATCH_0 (12):   8 + 12 + 1 + 35 = 56; 84; 86                        =    86
//   vreq on DVPR_VREQ_1 (11):     8 + 11 + 1 + 25032 = 25052; + UDP 8 = 25060 IP data
//                                 = 16 x 1480 + 1380: 16 x 1500 + 1400 + 17 x 2       = 25434
//   vres on DVPR_VRES_0 (11):     8 + 11 + 1 + 33 = 53; 81; 83                        =    83
//   table on DVPR_TABLE (10):     8 + 10 + 1 + 1568 = 1587; + 8 = 1595 = 1480 + 115:
//                                 1500 + 135 + 2 x 2                                  =  1639
//   DVPR_HEARTBEAT (14), 10 bytes: 8 + 14 + 1 + 10 = 33; 61; 63                       =    63
class RoleBytesTest : public ::testing::Test {
 protected:
  void SetUp() override {
    network_.SetOffline(NodeId(2), SimTime::Zero());
    query_t q;
    q.utime = 0;
    q.robot = 0;
    q.frame = 7;
    q.dim = 128;
    q.descriptor.assign(128, 0.5f);
    match_t m{};
    verify_request_t vreq{};
    vreq.payload_size = 25000;
    vreq.payload.assign(25000, 0);
    verify_result_t vres{};
    centroid_table_t table{};
    table.k = 3;
    table.dim = 128;
    table.centroids.assign(3, std::vector<float>(128, 0.0f));
    table.owners.assign(3, 0);
    ASSERT_EQ(Encode(q).size(), 544u);
    ASSERT_EQ(Encode(m).size(), 35u);
    ASSERT_EQ(Encode(vreq).size(), 25032u);
    ASSERT_EQ(Encode(vres).size(), 33u);
    ASSERT_EQ(Encode(table).size(), 1568u);
    Send(0, {1}, channels::Query(RobotId(1)), Encode(q));
    Send(1, {0}, channels::Match(RobotId(0)), Encode(m));
    Send(0, {1, 2}, channels::kQueryAll, Encode(q));
    Send(1, {0}, channels::Match(RobotId(0)), Encode(m));
    Send(2, {0}, channels::Match(RobotId(0)), Encode(m));  // offline sender: dropped, no medium use
    Send(0, {1}, channels::VerifyRequest(RobotId(1)), Encode(vreq));
    Send(1, {0}, channels::VerifyResult(RobotId(0)), Encode(vres));
    Send(0, {1, 2}, channels::kTable, Encode(table));
    Send(0, {1}, "DVPR_HEARTBEAT", std::vector<std::uint8_t>(10, 0));
    sim_.Run();
  }
  void Send(int src, std::vector<int> dsts, const std::string& channel, std::vector<std::uint8_t> payload) {
    std::vector<NodeId> ids;
    for (int d : dsts) ids.push_back(NodeId(d));
    network_.SendTo(NodeId(src), ids, network_.InternChannel(channel), network_.InternType("t"), std::move(payload));
  }

  Simulator sim_;
  Network network_{sim_, 3,
                   std::make_unique<SharedMediumLink>(SharedMediumParams{DataRate::Mbps(1000), SimTime::Millis(1), 100}, 3)};
  RoleBytesRecorder recorder_{3};
  ObserverSubscription subscription_ = network_.Subscribe(recorder_);
};

TEST_F(RoleBytesTest, PinsTheHandWorkedBytesOfEachRole) {
  const RunRoleBytes run = recorder_.Run();
  const auto& c = run.copies;
  // Offered: every copy sent; delivered: robot 2 neither receives nor sends.
  EXPECT_EQ(c[Role(MessageRole::kQuery)].payload, 3 * 544);
  EXPECT_EQ(c[Role(MessageRole::kQuery)].wire, 595 + 2 * 597);
  EXPECT_EQ(c[Role(MessageRole::kQuery)].delivered_payload, 2 * 544);
  EXPECT_EQ(c[Role(MessageRole::kQuery)].delivered_wire, 595 + 597);
  EXPECT_EQ(c[Role(MessageRole::kReply)].payload, 3 * 35);
  EXPECT_EQ(c[Role(MessageRole::kReply)].wire, 3 * 86);
  EXPECT_EQ(c[Role(MessageRole::kReply)].delivered_payload, 2 * 35);
  EXPECT_EQ(c[Role(MessageRole::kReply)].delivered_wire, 2 * 86);
  EXPECT_EQ(c[Role(MessageRole::kVerifyRequest)].payload, 25032);
  EXPECT_EQ(c[Role(MessageRole::kVerifyRequest)].wire, 25434);
  EXPECT_EQ(c[Role(MessageRole::kVerifyRequest)].delivered_wire, 25434);
  EXPECT_EQ(c[Role(MessageRole::kVerifyResult)].payload, 33);
  EXPECT_EQ(c[Role(MessageRole::kVerifyResult)].delivered_wire, 83);
  EXPECT_EQ(c[Role(MessageRole::kRecluster)].payload, 2 * 1568);
  EXPECT_EQ(c[Role(MessageRole::kRecluster)].wire, 2 * 1639);
  EXPECT_EQ(c[Role(MessageRole::kRecluster)].delivered_payload, 1568);
  EXPECT_EQ(c[Role(MessageRole::kOther)].payload, 10);
  EXPECT_EQ(c[Role(MessageRole::kOther)].wire, 63);
  // The medium carries a shared-medium broadcast once; the offline robot's reply not at all.
  EXPECT_EQ(run.medium[Role(MessageRole::kQuery)], 595 + 597);
  EXPECT_EQ(run.medium[Role(MessageRole::kReply)], 2 * 86);
  EXPECT_EQ(run.medium[Role(MessageRole::kVerifyRequest)], 25434);
  EXPECT_EQ(run.medium[Role(MessageRole::kVerifyResult)], 83);
  EXPECT_EQ(run.medium[Role(MessageRole::kRecluster)], 1639);
  EXPECT_EQ(run.medium[Role(MessageRole::kOther)], 63);
}

TEST_F(RoleBytesTest, PinsTheBytesOfEachDirectedPair) {
  const auto& to2 = recorder_.Pair(0, 2);
  EXPECT_EQ(to2[Role(MessageRole::kQuery)].payload, 544);
  EXPECT_EQ(to2[Role(MessageRole::kQuery)].wire, 597);
  EXPECT_EQ(to2[Role(MessageRole::kQuery)].delivered_wire, 0);
  EXPECT_EQ(to2[Role(MessageRole::kRecluster)].wire, 1639);
  EXPECT_EQ(to2[Role(MessageRole::kRecluster)].delivered_payload, 0);
  const auto& from2 = recorder_.Pair(2, 0);
  EXPECT_EQ(from2[Role(MessageRole::kReply)].wire, 86);
  EXPECT_EQ(from2[Role(MessageRole::kReply)].delivered_wire, 0);
  const auto& from1 = recorder_.Pair(1, 0);
  EXPECT_EQ(from1[Role(MessageRole::kReply)].delivered_wire, 2 * 86);
  EXPECT_EQ(from1[Role(MessageRole::kVerifyResult)].delivered_payload, 33);
  EXPECT_EQ(recorder_.Pair(1, 2)[Role(MessageRole::kReply)].wire, 0);
}

TEST_F(RoleBytesTest, RolesSumToTheNetworksOwnTotals) {
  const RunRoleBytes run = recorder_.Run();
  std::int64_t payload = 0, wire = 0, medium = 0;
  for (int r = 0; r < kMessageRoles; ++r) {
    payload += run.copies[static_cast<std::size_t>(r)].payload;
    wire += run.copies[static_cast<std::size_t>(r)].wire;
    medium += run.medium[static_cast<std::size_t>(r)];
  }
  const LinkCounters totals = network_.Totals();
  EXPECT_EQ(payload, totals.payload_bytes);
  EXPECT_EQ(wire, totals.wire_bytes);
  std::int64_t sent_on_medium = 0;
  for (int s = 0; s < 3; ++s) sent_on_medium += network_.Sender(NodeId(s)).medium_bytes;
  EXPECT_EQ(medium, sent_on_medium);
  EXPECT_EQ(medium, 595 + 597 + 2 * 86 + 25434 + 83 + 1639 + 63);
}

}  // namespace
}  // namespace dvpr

namespace dvpr {
namespace {

// The recorder fed directly, in a team of 300 (beyond PairMap's dense table: each role's pairs
// in a hash table of their own). Hand-worked: 299 -> 5 sends a query (payload 544, wire 597) and
// 5 -> 299 a reply (35, 86) twice, the second reply lost; 7 -> 3 a heartbeat (10, 63). The pairs
// listed are the union over the roles, by source then destination: 5->299, 7->3, 299->5.
TEST(RoleBytesRecorderTest, ALargeTeamKeepsEachRolesPairsAndListsTheirUnionInOrder) {
  Simulator sim;
  Network network(sim, 300, std::make_unique<SharedMediumLink>(SharedMediumParams{}, 300));
  const ChannelId query = network.InternChannel(channels::kQueryAll);
  const ChannelId reply = network.InternChannel(channels::Match(RobotId(299)));
  const ChannelId heartbeat = network.InternChannel("DVPR_HEARTBEAT");
  const std::vector<std::uint8_t> q(544), m(35), h(10);
  const auto copy = [&](int src, int dst, ChannelId channel, const std::vector<std::uint8_t>& payload, std::int64_t wire) {
    MessageCopy c;
    c.src = NodeId(src);
    c.dst = NodeId(dst);
    c.channel = channel;
    c.channel_name = network.ChannelName(channel);
    c.payload = payload;
    c.wire_bytes = wire;
    return c;
  };
  RoleBytesRecorder recorder(300);
  recorder.OnSent(copy(299, 5, query, q, 597));
  recorder.OnDelivered(copy(299, 5, query, q, 597), SimTime::Zero());
  recorder.OnSent(copy(5, 299, reply, m, 86));
  recorder.OnDelivered(copy(5, 299, reply, m, 86), SimTime::Zero());
  recorder.OnSent(copy(5, 299, reply, m, 86));
  recorder.OnSent(copy(7, 3, heartbeat, h, 63));
  MediumReport medium;
  medium.channel = reply;
  medium.channel_name = network.ChannelName(reply);
  medium.bytes = 86;
  recorder.OnMedium(medium);

  const RoleCopyBytes to_querier = recorder.Pair(5, 299);
  EXPECT_EQ(to_querier[Role(MessageRole::kReply)].payload, 70);
  EXPECT_EQ(to_querier[Role(MessageRole::kReply)].wire, 172);
  EXPECT_EQ(to_querier[Role(MessageRole::kReply)].delivered_payload, 35);
  EXPECT_EQ(to_querier[Role(MessageRole::kReply)].delivered_wire, 86);
  EXPECT_EQ(to_querier[Role(MessageRole::kQuery)].wire, 0);
  EXPECT_EQ(recorder.Pair(299, 5)[Role(MessageRole::kQuery)].delivered_wire, 597);
  EXPECT_EQ(recorder.Pair(3, 7)[Role(MessageRole::kOther)].wire, 0);  // the other direction carried nothing

  std::vector<std::pair<int, int>> pairs;
  std::int64_t wire = 0;
  recorder.ForEachPair([&](NodeId src, NodeId dst, const RoleCopyBytes& bytes) {
    pairs.emplace_back(src.value, dst.value);
    for (const CopyBytes& c : bytes) wire += c.wire;
  });
  EXPECT_EQ(pairs, (std::vector<std::pair<int, int>>{{5, 299}, {7, 3}, {299, 5}}));
  EXPECT_EQ(wire, 597 + 2 * 86 + 63);

  const RunRoleBytes run = recorder.Run();
  EXPECT_EQ(run.copies[Role(MessageRole::kQuery)].payload, 544);
  EXPECT_EQ(run.copies[Role(MessageRole::kReply)].delivered_wire, 86);
  EXPECT_EQ(run.copies[Role(MessageRole::kOther)].payload, 10);
  EXPECT_EQ(run.medium[Role(MessageRole::kReply)], 86);
  EXPECT_EQ(run.medium[Role(MessageRole::kQuery)], 0);
}

}  // namespace
}  // namespace dvpr
