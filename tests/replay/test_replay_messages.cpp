// Reading messages.csv for a replay: which run is selected, what each row becomes, the errors.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "experiments/replay/replay_messages.h"
#include "tests/replay/replay_test_support.h"

namespace dvpr::replay {
namespace {

// A network variant's label as the folder's config gives it (VariantLabels).
NetworkLabel Net(int variant, const std::string& model, double bps, double ms, const std::string& propagation = "",
                 double range_m = kNotApplicable, const std::string& next_hop = "") {
  return NetworkLabel{.variant = variant, .model = model, .bandwidth_bps = bps, .latency_ms = ms, .loss = "none",
                      .propagation = propagation, .range_m = range_m, .next_hop = next_hop};
}
const std::vector<NetworkLabel> kP2p = {Net(0, "point_to_point", 1e7, 2)};

class ReplayMessagesTest : public ReplayFolderTest {
 protected:
  // File()'s two network variants.
  static std::vector<NetworkLabel> Networks() { return {Net(0, "point_to_point", 1e7, 2), Net(1, "shared_medium", 1e6, 0.5)}; }
  // Two runs of 3 robots on network 0 and one on network 1; broadcast listed before decentralized.
  std::filesystem::path File() const {
    return Write("messages.csv", std::string(kHeader) +
        "lcm,decentralized,3,0,5,9,0,1,DVPR_QUERY_1,x,query_t,536,587,0,0,point_to_point,1e+07,2,none,q\n"
        "sim,broadcast,3,0,0,2469600,0,1,DVPR_QUERY_ALL,x,query_t,536,589,0,0,point_to_point,1e+07,2,none,q\n"
        "sim,broadcast,3,0,0,,0,2,DVPR_QUERY_ALL,x,query_t,536,589,1,0,point_to_point,1e+07,2,none,q\n"
        "sim,decentralized,3,0,1499,,1,2,DVPR_MATCH_2,x,match_t,40,95,0,0,point_to_point,1e+07,2,none,r\n"
        "sim,decentralized,3,0,2000,30000000,2,0,DVPR_VREQ_0,x,verify_request_t,25000,25900,0,0,point_to_point,1e+07,2,none,v\n"
        "sim,decentralized,3,1,7,8,1,0,DVPR_QUERY_0,x,query_t,536,587,0,0,point_to_point,1e+07,2,none,q\n"
        "sim,decentralized,3,0,100,200,1,0,DVPR_QUERY_0,x,query_t,536,587,0,1,shared_medium,1e+06,0.5,none,q\n");
  }
};

TEST_F(ReplayMessagesTest, DefaultsToTheFirstSimRunAndTheTwoStrategiesOfThePaper) {
  const ReplayRun run = ReadReplayRun(File(), {}, Networks());
  EXPECT_EQ(run.robots, 3);
  EXPECT_EQ(run.run, 0);
  EXPECT_EQ(run.network_variant, 0);
  EXPECT_EQ(run.network.model, "point_to_point");
  EXPECT_EQ(run.network.bandwidth_bps, 1e7);
  EXPECT_EQ(run.network.latency_ms, 2.0);
  EXPECT_EQ(run.network.loss, "none");
  ASSERT_EQ(run.strategies.size(), 2u);
  EXPECT_EQ(run.strategies[0].strategy, "decentralized");  // the paper's method first, whatever the file order
  EXPECT_EQ(run.strategies[1].strategy, "broadcast");
  ASSERT_EQ(run.strategies[0].messages.size(), 2u);         // not the lcm row, not run 1, not network 1
  ASSERT_EQ(run.strategies[1].messages.size(), 2u);
}

TEST_F(ReplayMessagesTest, EachRowAsTheReplayNeedsIt) {
  const ReplayRun run = ReadReplayRun(File(), {}, Networks());
  const Message& reply = run.strategies[0].messages[0];
  EXPECT_EQ(reply.sent_ns, 1499);
  EXPECT_EQ(reply.delivered_ns, -1);  // in flight when the run ended: not delivered, not dropped
  EXPECT_FALSE(reply.dropped);
  EXPECT_EQ(reply.src, 1);
  EXPECT_EQ(reply.dst, 2);
  EXPECT_EQ(reply.role, MessageRole::kReply);
  EXPECT_EQ(reply.queue, QueueEffect::kAnswer);
  EXPECT_EQ(reply.counted_bytes, 95);
  const Message& verify = run.strategies[0].messages[1];
  EXPECT_EQ(verify.delivered_ns, 30000000);
  EXPECT_EQ(verify.role, MessageRole::kVerifyRequest);
  EXPECT_EQ(verify.counted_bytes, 25900);
  const Message& dropped = run.strategies[1].messages[1];
  EXPECT_TRUE(dropped.dropped);
  EXPECT_EQ(dropped.delivered_ns, -1);
  EXPECT_EQ(dropped.counted_bytes, 589);  // point-to-point: each copy is its own transmission
}

TEST_F(ReplayMessagesTest, SelectsRunNetworkAndStrategies) {
  Selection s;
  s.run = 1;
  const ReplayRun one = ReadReplayRun(File(), s, Networks());
  EXPECT_EQ(one.run, 1);
  ASSERT_EQ(one.strategies.size(), 1u);  // run 1 has only the paper's method
  EXPECT_EQ(one.strategies[0].messages.at(0).sent_ns, 7);
  Selection net;
  net.network = 1;
  const ReplayRun shared = ReadReplayRun(File(), net, Networks());
  EXPECT_EQ(shared.network.model, "shared_medium");
  EXPECT_EQ(shared.network.bandwidth_bps, 1e6);
  EXPECT_EQ(shared.network.latency_ms, 0.5);
  Selection only;
  only.strategies = {"broadcast"};
  const ReplayRun b = ReadReplayRun(File(), only, Networks());
  ASSERT_EQ(b.strategies.size(), 1u);
  EXPECT_EQ(b.strategies[0].strategy, "broadcast");
}

TEST_F(ReplayMessagesTest, ASelectionTheFileDoesNotHoldSaysWhatItHas) {
  const std::filesystem::path f = File();
  Selection s;
  s.run = 7;
  EXPECT_EQ(ErrorOf([&] { ReadReplayRun(f, s, Networks()); }),
            f.string() + ": no messages of run=7 (it has robots 3; runs 0, 1; network variants 0, 1)");
  Selection strategy;
  strategy.strategies = {"multi_probe_2"};
  EXPECT_EQ(ErrorOf([&] { ReadReplayRun(f, strategy, Networks()); }),
            f.string() + ": no messages of strategy 'multi_probe_2' in robots=3 run=0 (it has: broadcast, decentralized)");
}

TEST_F(ReplayMessagesTest, ASharedMediumBroadcastCountsOnce) {
  const auto f = Write("messages.csv", std::string(kHeader) +
      "sim,broadcast,3,0,0,10,0,1,DVPR_QUERY_ALL,x,query_t,536,589,0,0,shared_medium,1e+07,2,none,q\n"
      "sim,broadcast,3,0,0,10,0,2,DVPR_QUERY_ALL,x,query_t,536,589,0,0,shared_medium,1e+07,2,none,q\n"
      "sim,broadcast,3,0,0,20,0,2,DVPR_VREQ_2,x,verify_request_t,900,990,0,0,shared_medium,1e+07,2,none,v\n"
      "sim,broadcast,3,0,5,30,0,1,DVPR_QUERY_ALL,x,query_t,536,589,0,0,shared_medium,1e+07,2,none,q\n"
      "sim,broadcast,3,0,5,30,0,2,DVPR_QUERY_ALL,x,query_t,536,589,0,0,shared_medium,1e+07,2,none,q\n"
      "sim,broadcast,3,0,5,30,1,0,DVPR_QUERY_ALL,x,query_t,536,589,0,0,shared_medium,1e+07,2,none,q\n");
  const ReplayRun run = ReadReplayRun(f, {}, std::vector<NetworkLabel>{Net(0, "shared_medium", 1e7, 2)});
  std::vector<std::int64_t> counted;
  for (const Message& m : run.strategies.at(0).messages) counted.push_back(m.counted_bytes);
  EXPECT_EQ(counted, (std::vector<std::int64_t>{589, 0, 990, 589, 0, 589}));  // the last: another sender
}

// Issue 53: where one transmission reaches every robot (shared_medium, csma, wifi, a radio that
// does not relay) runs.csv's wire_bytes counts a broadcast once, and so does the page. Robot 0
// broadcasts a 589-byte query to robots 1, 2, 3 and, at the same instant, sends a 990-byte
// verification request to robot 2; robot 2 replies with 95 bytes: three transmissions,
// 589 + 990 + 95 = 1674 bytes (per copy, as point-to-point links carry them: 3 x 589 + 990 + 95
// = 2852).
TEST_F(ReplayMessagesTest, ABroadcastOnAMediumEveryoneHearsCountsOnceAsRunsCsvWireBytes) {
  const std::string header =
      "protocol,strategy,robots,run,sent_ns,delivered_ns,src,dst,channel,wire_bytes,dropped,network_variant,"
      "network_model,bandwidth_bps,latency_ms,loss,network_name\n";
  const auto total = [&](const NetworkLabel& label) {
    const std::string net = "," + label.model + ",1e+07," + (std::isnan(label.latency_ms) ? "" : "2") + ",none," +
                            NetworkName(label) + "\n";
    const auto f = Write(label.model + ".csv", header +
        "sim,broadcast,4,0,0,10,0,1,DVPR_QUERY_ALL,589,0,0" + net +
        "sim,broadcast,4,0,0,10,0,2,DVPR_QUERY_ALL,589,0,0" + net +
        "sim,broadcast,4,0,0,,0,3,DVPR_QUERY_ALL,589,1,0" + net +
        "sim,broadcast,4,0,0,20,0,2,DVPR_VREQ_2,990,0,0" + net +
        "sim,broadcast,4,0,30,40,2,0,DVPR_MATCH_0,95,0,0" + net);
    const ReplayRun run = ReadReplayRun(f, {}, std::vector<NetworkLabel>{label});
    std::int64_t sum = 0;
    for (const Message& m : run.strategies.at(0).messages) sum += m.counted_bytes;
    return sum;
  };
  EXPECT_EQ(total(Net(0, "shared_medium", 1e7, 2)), 1674);
  EXPECT_EQ(total(Net(0, "csma", 1e7, 2)), 1674);
  EXPECT_EQ(total(Net(0, "wifi", 1e7, kNotApplicable)), 1674);
  EXPECT_EQ(total(Net(0, "radio", 1e7, 2, "range 200m", 200)), 1674);  // direct: no relays
  EXPECT_EQ(total(Net(0, "point_to_point", 1e7, 2)), 2852);
}

// Issue 53: wifi has no latency (its air delay is the propagation's) and ideal neither a rate:
// their fields are empty, read as not applicable, not refused.
TEST_F(ReplayMessagesTest, AWifiOrIdealRunHasNoLatencyToRead) {
  const auto wifi = Write("wifi.csv", std::string(kHeader) +
      "sim,broadcast,3,0,0,10,0,1,DVPR_QUERY_ALL,x,query_t,536,589,0,0,wifi,6e+06,,none,q\n");
  const std::vector<NetworkLabel> wifi_net = {Net(0, "wifi", 6e6, kNotApplicable)};
  const ReplayRun w = ReadReplayRun(wifi, {}, wifi_net);
  EXPECT_EQ(w.network.model, "wifi");
  EXPECT_EQ(w.network.bandwidth_bps, 6e6);
  EXPECT_TRUE(std::isnan(w.network.latency_ms));
  const auto ideal = Write("ideal.csv", std::string(kHeader) +
      "sim,broadcast,3,0,0,0,0,1,DVPR_QUERY_ALL,x,query_t,536,589,0,0,ideal,,,none,q\n");
  const ReplayRun i = ReadReplayRun(ideal, {}, std::vector<NetworkLabel>{Net(0, "ideal", kNotApplicable, kNotApplicable)});
  EXPECT_TRUE(std::isnan(i.network.bandwidth_bps));
  EXPECT_TRUE(std::isnan(i.network.latency_ms));
  const auto bad = Write("bad.csv", std::string(kHeader) +
      "sim,broadcast,3,0,0,10,0,1,DVPR_QUERY_ALL,x,query_t,536,589,0,0,wifi,6e+06,soon,none,q\n");
  EXPECT_EQ(ErrorOf([&] { ReadReplayRun(bad, {}, wifi_net); }), bad.string() + ": line 2: latency_ms: expected a number, got 'soon'");
}

// Issue 53: hops that no network gives are refused, naming file, line and column. Without relays
// a copy makes one transmission (0 when lost before it); a delivered copy made at least one; a
// relaying radio drops a copy at its 64th relay (hop_limit). More than robots - 1 hops is not
// refused: relays may hand a copy back while the graph changes (docs/network_model.md).
TEST_F(ReplayMessagesTest, HopsNoNetworkGivesAreRefused) {
  const std::string header =
      "protocol,strategy,robots,run,sent_ns,delivered_ns,src,dst,channel,wire_bytes,dropped,network_variant,"
      "network_model,bandwidth_bps,latency_ms,loss,network_name,hops\n";
  // network_variant to hops of a radio with relays; a row puts its dropped field before it.
  const std::string relaying = ",0,radio,1e+07,2,none,radio 10 Mbit/s 2 ms range 200m shortest_path,";
  const std::vector<NetworkLabel> relays = {Net(0, "radio", 1e7, 2, "range 200m", 200, "shortest_path")};
  const auto error = [&](const std::string& name, const std::string& rows,
                         const std::vector<NetworkLabel>& networks) {
    const auto f = Write(name, header + rows);
    const std::string e = ErrorOf([&] { ReadReplayRun(f, {}, networks); });
    return e.rfind(f.string() + ": ", 0) == 0 ? e.substr(f.string().size() + 2) : e;
  };
  EXPECT_EQ(error("p2p.csv",
                  "sim,broadcast,3,0,0,10,0,1,DVPR_QUERY_ALL,589,0,0,point_to_point,1e+07,2,none,p2p,1\n"
                  "sim,broadcast,3,0,0,10,0,2,DVPR_QUERY_ALL,589,0,0,point_to_point,1e+07,2,none,p2p,2\n", kP2p),
            "line 3: hops: expected at most 1 (one transmission: network point_to_point has no relays), got 2");
  EXPECT_EQ(error("direct.csv",
                  "sim,broadcast,3,0,0,10,0,1,DVPR_QUERY_ALL,589,0,0,radio,1e+07,2,none,radio 10 Mbit/s 2 ms range 200m,2\n",
                  {Net(0, "radio", 1e7, 2, "range 200m", 200)}),
            "line 2: hops: expected at most 1 (one transmission: network radio has no relays), got 2");
  EXPECT_EQ(error("pair.csv", "sim,broadcast,2,0,0,10,0,1,DVPR_QUERY_ALL,589,0" + relaying + "2\n", relays),
            "line 2: hops: expected at most 1 (one transmission: a team of 2 has no robot to relay), got 2");
  EXPECT_EQ(error("limit.csv", "sim,broadcast,3,0,0,,0,1,DVPR_QUERY_ALL,589,1" + relaying + "65\n", relays),
            "line 2: hops: expected at most 64 (a relay drops a copy after 64 transmissions, hop_limit), got 65");
  EXPECT_EQ(error("zero.csv", "sim,broadcast,3,0,0,10,0,1,DVPR_QUERY_ALL,589,0" + relaying + "0\n", relays),
            "line 2: hops: expected at least 1 for a delivered copy, got 0");
  // What a relaying team of 3 can give: 64 hops (dropped hop_limit), 3 (handed back once), 0 (lost
  // before its first transmission).
  const auto fine = Write("fine.csv", header +
      "sim,broadcast,3,0,0,,0,1,DVPR_QUERY_ALL,589,1" + relaying + "64\n"
      "sim,broadcast,3,0,0,10,0,2,DVPR_QUERY_ALL,589,0" + relaying + "3\n"
      "sim,broadcast,3,0,5,,0,1,DVPR_QUERY_ALL,589,1" + relaying + "0\n");
  const ReplayRun run = ReadReplayRun(fine, {}, relays);
  std::vector<int> hops;
  for (const Message& m : run.strategies.at(0).messages) hops.push_back(m.hops);
  EXPECT_EQ(hops, (std::vector<int>{64, 3, 0}));
}

// A radio sweep's messages.csv ends with hops; its network_name carries the range, which the page
// draws (a log_distance radio has none). Without the columns every copy is one hop.
TEST_F(ReplayMessagesTest, ARadiosRangeAndHopsAreRead) {
  const std::string header =
      "protocol,strategy,robots,run,sent_ns,delivered_ns,src,dst,channel,wire_bytes,dropped,network_variant,"
      "network_model,bandwidth_bps,latency_ms,loss,network_name,role,hops\n";
  const auto f = Write("radio.csv", header +
      "sim,broadcast,3,0,0,10,0,2,DVPR_QUERY_ALL,589,0,1,radio,1e+07,2,none,radio 10 Mbit/s 2 ms range 1.5km shortest_path,query,2\n"
      "sim,broadcast,3,0,0,,0,1,DVPR_QUERY_ALL,589,1,1,radio,1e+07,2,none,radio 10 Mbit/s 2 ms range 1.5km shortest_path,query,0\n");
  const ReplayRun run =
      ReadReplayRun(f, {}, std::vector<NetworkLabel>{Net(0, "ideal", kNotApplicable, kNotApplicable), Net(1, "radio", 1e7, 2, "range 1.5km", 1500, "shortest_path")});
  EXPECT_EQ(run.network.range_m, 1500.0);
  EXPECT_EQ(NetworkName(run.network), "radio 10 Mbit/s 2 ms range 1.5km shortest_path");
  ASSERT_EQ(run.strategies.at(0).messages.size(), 2u);
  EXPECT_EQ(run.strategies[0].messages[0].hops, 2);
  EXPECT_EQ(run.strategies[0].messages[1].hops, 0);
  const auto log_distance = Write("log.csv", header +
      "sim,broadcast,3,0,0,10,0,2,DVPR_QUERY_ALL,589,0,1,radio,1e+07,2,none,radio 10 Mbit/s 2 ms log_distance link_state,query,1\n");
  const std::vector<NetworkLabel> log_net = {Net(0, "ideal", kNotApplicable, kNotApplicable),
                                             Net(1, "radio", 1e7, 2, "log_distance", kNotApplicable, "link_state")};
  EXPECT_TRUE(std::isnan(ReadReplayRun(log_distance, {}, log_net).network.range_m));
  const auto bad = Write("bad_hops.csv", header +
      "sim,broadcast,3,0,0,10,0,2,DVPR_QUERY_ALL,589,0,1,radio,1e+07,2,none,radio,query,-1\n");
  EXPECT_EQ(ErrorOf([&] { ReadReplayRun(bad, {}, log_net); }),
            bad.string() + ": line 2: hops: expected a count of at least 0, got -1");
  const auto plain = Write("plain.csv", std::string(kHeader) +
      "sim,broadcast,3,0,0,10,0,1,DVPR_QUERY_ALL,x,query_t,536,589,0,0,point_to_point,1e+07,2,none,q\n");
  const ReplayRun p2p = ReadReplayRun(plain, {}, kP2p);
  EXPECT_TRUE(std::isnan(p2p.network.range_m));
  EXPECT_EQ(p2p.strategies.at(0).messages.at(0).hops, 1);
}

TEST_F(ReplayMessagesTest, FilesThatCannotBeReplayedAreOneLineNamingTheFile) {
  const auto none = Write("none.csv", std::string(kHeader));
  EXPECT_EQ(ErrorOf([&] { ReadReplayRun(none, {}, kP2p); }),
            none.string() + ": no messages of protocol sim (a replay needs a simulated run with outputs.messages: true)");
  const auto header = Write("header.csv", "protocol,strategy,robots,run,sent_ns\nsim,broadcast,3,0,0\n");
  EXPECT_EQ(ErrorOf([&] { ReadReplayRun(header, {}, kP2p); }),
            header.string() + ": no column 'delivered_ns' in its header (is this a dvpr messages.csv?)");
  const auto bad = Write("bad.csv", std::string(kHeader) +
      "sim,broadcast,3,0,zero,10,0,1,DVPR_QUERY_ALL,x,query_t,536,589,0,0,point_to_point,1e+07,2,none,q\n");
  EXPECT_EQ(ErrorOf([&] { ReadReplayRun(bad, {}, kP2p); }), bad.string() + ": line 2: sent_ns: expected a number, got 'zero'");
  const auto short_row = Write("short.csv", std::string(kHeader) + "sim,broadcast,3,0\n");
  EXPECT_EQ(ErrorOf([&] { ReadReplayRun(short_row, {}, kP2p); }),
            short_row.string() + ": line 2: expected 20 fields as in the header, got 4 (a cut or edited file?)");
  // Cut inside its last field (role, which the replay does not read) the row still has 20 fields;
  // cut one comma earlier it has 19 and is refused, though every column the replay reads is whole.
  const auto cut = Write("cut.csv", std::string(kHeader) +
      "sim,broadcast,3,0,0,10,0,1,DVPR_QUERY_ALL,x,query_t,536,589,0,0,point_to_point,1e+07,2,none,q\n"
      "sim,broadcast,3,0,0,10,0,2,DVPR_QUERY_ALL,x,query_t,536,589,0,0,point_to_point,1e+07,2,none\n");
  EXPECT_EQ(ErrorOf([&] { ReadReplayRun(cut, {}, kP2p); }),
            cut.string() + ": line 3: expected 20 fields as in the header, got 19 (a cut or edited file?)");
  const auto unended = Write("unended.csv", std::string(kHeader) +
      "sim,broadcast,3,0,0,10,0,1,DVPR_QUERY_ALL,x,query_t,536,589,0,0,point_to_point,1e+07,2,none,q\n"
      "sim,broadcast,3,0,0,10,0,2,DVPR_QUERY_ALL,x,query_t,536,589,0,0,point_to_point,1e+07,2,none,q");
  EXPECT_EQ(ErrorOf([&] { ReadReplayRun(unended, {}, kP2p); }),
            unended.string() + ": line 3: the file ends inside it (no line end: a cut file?)");
  const auto extra = Write("extra.csv", std::string(kHeader) +
      "sim,broadcast,3,0,0,10,0,1,DVPR_QUERY_ALL,x,query_t,536,589,0,0,point_to_point,1e+07,2,none,q,more\n");
  EXPECT_EQ(ErrorOf([&] { ReadReplayRun(extra, {}, kP2p); }),
            extra.string() + ": line 2: expected 20 fields as in the header, got 21 (a cut or edited file?)");
  const auto empty = Write("empty.csv", "");
  EXPECT_EQ(ErrorOf([&] { ReadReplayRun(empty, {}, kP2p); }), empty.string() + ": empty file (no header)");
  EXPECT_EQ(ErrorOf([&] { ReadReplayRun(dir_ / "absent.csv", {}, kP2p); }), (dir_ / "absent.csv").string() + ": cannot open it");
}

// The page draws src and dst as indexes into the team: a robot outside it is refused (the page's
// script failed on it), naming file, line and column.
TEST_F(ReplayMessagesTest, RobotsOutsideTheTeamAreRefused) {
  const auto dst = Write("dst.csv", std::string(kHeader) +
      "sim,broadcast,3,0,0,10,0,1,DVPR_QUERY_ALL,x,query_t,536,589,0,0,point_to_point,1e+07,2,none,q\n"
      "sim,broadcast,3,0,0,10,0,3,DVPR_QUERY_ALL,x,query_t,536,589,0,0,point_to_point,1e+07,2,none,q\n");
  EXPECT_EQ(ErrorOf([&] { ReadReplayRun(dst, {}, kP2p); }),
            dst.string() + ": line 3: dst: expected a robot of the team of 3 (0 to 2), got 3");
  const auto src = Write("src.csv", std::string(kHeader) +
      "sim,broadcast,3,0,0,10,-1,1,DVPR_QUERY_ALL,x,query_t,536,589,0,0,point_to_point,1e+07,2,none,q\n");
  EXPECT_EQ(ErrorOf([&] { ReadReplayRun(src, {}, kP2p); }),
            src.string() + ": line 2: src: expected a robot of the team of 3 (0 to 2), got -1");
}

// The folder's config.yaml names each variant's network; a messages.csv whose selected run is on
// another network (or a variant the config does not have) is another config's: refused, naming the
// line, not replayed with the wrong relays or range.
TEST_F(ReplayMessagesTest, ARunOnAnotherNetworkThanTheConfigsVariantIsRefused) {
  const std::filesystem::path f = File();
  EXPECT_EQ(ErrorOf([&] { ReadReplayRun(f, {}, std::vector<NetworkLabel>{Net(0, "radio", 1e7, 2, "range 200m", 200)}); }),
            f.string() + ": line 3: network_model: expected network variant 0 of the folder's config.yaml "
                         "('radio 10 Mbit/s 2 ms range 200m'), got 'point-to-point 10 Mbit/s 2 ms'");
  Selection net;
  net.network = 1;
  EXPECT_EQ(ErrorOf([&] { ReadReplayRun(f, net, kP2p); }),
            f.string() + ": line 8: network_variant: expected a network variant of the folder's config.yaml (it has 1), got 1");
}

}  // namespace
}  // namespace dvpr::replay
