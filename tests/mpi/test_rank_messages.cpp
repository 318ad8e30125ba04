// The messages between the ranks of a distributed sweep carry every field of a run's output
// unchanged (doubles bit for bit, NaN and -0 too), so rank 0 writes what the run computed.
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "experiments/mpi/rank_messages.h"

namespace {

using namespace dvpr;

std::uint64_t Bits(double v) { return std::bit_cast<std::uint64_t>(v); }

RunKey Key() {
  RunKey k;
  k.protocol = "sim";
  k.strategy = "multi_probe_2";
  k.robots = 7;
  k.run = 3;
  k.network = NetworkLabel{2, "shared_medium", 1e7, 2.5, "gilbert_elliott", 8, 9000, "range 150m", 150.25, "shortest_path"};
  return k;
}

// One row of every kind, each field a value of its own.
RunOutput Sample() {
  RunOutput o;
  RunResult r;
  r.key = Key();
  r.seed = 0xfedcba9876543210ULL;
  r.auc = 0.1 + 0.2;                                  // 0.30000000000000004
  r.auc_reference = -0.0;
  r.relative_auc = std::numeric_limits<double>::denorm_min();
  r.worst_balance_ratio = kNotApplicable;
  r.queries = -1;
  r.messages = std::numeric_limits<std::int64_t>::max();
  r.payload_bytes = 123456789012LL;
  r.wire_bytes = 5;
  r.bytes_per_query = std::numeric_limits<double>::infinity();
  r.mean_latency_ms = 1.0 / 3.0;
  r.p99_latency_ms = 9.75;
  r.dropped_messages = 42;
  r.closures = RunClosures{.inter_queries = 17, .intra_queries = 1, .inter_recognised = 3, .intra_recognised = 1,
                           .inter_auc = 0.1 + 0.2, .intra_auc = kNotApplicable, .inter_candidates = 3,
                           .inter_closures = 2, .pairs_closed = 1, .median_first_closure_ns = 30'000'000'001};
  o.runs = {r, RunResult{}};
  o.closure_pairs = {ClosurePairRow{Key(), 0, 1, 30'000'000'001}, ClosurePairRow{Key(), 0, 2, std::nullopt}};
  o.per_robot = {RobotLoadRow{Key(), 4, 10, 20, 30, 0.125, 6}};
  o.per_robot[0].mac_retries = 9;
  o.per_robot[0].airtime_share = 0.1 + 0.2;
  MediumRow m;
  m.key = Key();
  m.attempts = 1001;
  m.busy_ns = 150'000'000'001;
  m.utilisation = 1.0 / 3.0;
  m.dropped.back() = 5;  // collision
  o.medium = {m};
  o.links = {LinkRow{Key(), 1, 2, 3, 4, 5, 6, std::nullopt}};
  o.queries = {QueryRow{Key(), 1, 1559, 155900000000, 0, 12, 0.5, 777, true, false, "inter", 0},
               QueryRow{Key(), 2, 3, 4, std::nullopt, std::nullopt, kNotApplicable, std::nullopt, false, true, "", 3}};
  o.messages = {MessageRow{Key(), 10, std::nullopt, 0, 1, "DVPR_QUERY_1", "dvpr.query_t", 547, 600, true, ""}};
  o.curves = {PrCurve{std::string("centralized\0\n,", 14), 10, 0, {0.0, 0.5, 1.0}, {1.0, 0.75, 0.5}}};
  return o;
}

void ExpectSameKey(const RunKey& a, const RunKey& b) {
  EXPECT_EQ(a.protocol, b.protocol);
  EXPECT_EQ(a.strategy, b.strategy);
  EXPECT_EQ(a.robots, b.robots);
  EXPECT_EQ(a.run, b.run);
  EXPECT_EQ(a.network.variant, b.network.variant);
  EXPECT_EQ(a.network.model, b.network.model);
  EXPECT_EQ(Bits(a.network.bandwidth_bps), Bits(b.network.bandwidth_bps));
  EXPECT_EQ(Bits(a.network.latency_ms), Bits(b.network.latency_ms));
  EXPECT_EQ(a.network.loss, b.network.loss);
}

TEST(RankMessagesTest, OutputArrivesFieldForFieldAndBitForBit) {
  const RunOutput sent = Sample();
  const IndexedOutput got = DecodeOutput(EncodeOutput(11, sent));
  EXPECT_EQ(got.index, 11u);
  const RunOutput& o = got.output;
  ASSERT_EQ(o.runs.size(), 2u);
  const RunResult& r = o.runs[0];
  ExpectSameKey(r.key, Key());
  EXPECT_EQ(r.seed, 0xfedcba9876543210ULL);
  EXPECT_EQ(Bits(r.auc), 0x3fd3333333333334ULL);    // 0.1 + 0.2 in IEEE 754, not 0.3
  EXPECT_EQ(Bits(r.auc_reference), 0x8000000000000000ULL);  // -0, not +0
  EXPECT_EQ(Bits(r.relative_auc), 1u);                        // the smallest denormal
  EXPECT_EQ(Bits(r.worst_balance_ratio), Bits(kNotApplicable));
  EXPECT_EQ(r.queries, -1);
  EXPECT_EQ(r.messages, std::numeric_limits<std::int64_t>::max());
  EXPECT_EQ(r.payload_bytes, 123456789012LL);
  EXPECT_EQ(r.wire_bytes, 5);
  EXPECT_TRUE(std::isinf(r.bytes_per_query));
  EXPECT_EQ(Bits(r.mean_latency_ms), Bits(1.0 / 3.0));
  EXPECT_EQ(r.p99_latency_ms, 9.75);
  EXPECT_EQ(r.dropped_messages, 42);
  ASSERT_TRUE(r.closures.has_value());
  EXPECT_EQ(r.closures->inter_queries, 17);
  EXPECT_EQ(r.closures->intra_recognised, 1);
  EXPECT_EQ(Bits(r.closures->inter_auc), 0x3fd3333333333334ULL);
  EXPECT_TRUE(std::isnan(r.closures->intra_auc));
  EXPECT_EQ(r.closures->inter_closures, 2);
  EXPECT_EQ(r.closures->median_first_closure_ns, 30'000'000'001);
  EXPECT_FALSE(o.runs[1].closures.has_value());
  ASSERT_EQ(o.closure_pairs.size(), 2u);
  EXPECT_EQ(o.closure_pairs[0].robot_b, 1);
  EXPECT_EQ(o.closure_pairs[0].first_closure_ns, 30'000'000'001);
  EXPECT_EQ(o.closure_pairs[1].robot_b, 2);
  EXPECT_FALSE(o.closure_pairs[1].first_closure_ns.has_value());
  EXPECT_EQ(o.runs[1].key.protocol, "");
  ASSERT_EQ(o.per_robot.size(), 1u);
  EXPECT_EQ(o.per_robot[0].stored, 30);
  EXPECT_EQ(o.per_robot[0].mac_retries, 9);
  EXPECT_EQ(Bits(o.per_robot[0].airtime_share), 0x3fd3333333333334ULL);
  ASSERT_EQ(o.medium.size(), 1u);
  EXPECT_EQ(o.medium[0].attempts, 1001);
  EXPECT_EQ(o.medium[0].busy_ns, 150'000'000'001);
  EXPECT_EQ(Bits(o.medium[0].utilisation), Bits(1.0 / 3.0));
  EXPECT_EQ(o.medium[0].dropped.back(), 5);
  EXPECT_EQ(o.per_robot[0].busy_fraction, 0.125);
  EXPECT_EQ(o.per_robot[0].max_queue, 6);
  ASSERT_EQ(o.links.size(), 1u);
  EXPECT_EQ(o.links[0].dst, 2);
  EXPECT_EQ(o.links[0].dropped, 6);
  ASSERT_EQ(o.queries.size(), 2u);
  EXPECT_EQ(o.queries[0].frame, 1559);
  EXPECT_EQ(o.queries[0].match_robot, 0);  // present and zero, not empty
  EXPECT_EQ(o.queries[0].match_frame, 12);
  EXPECT_EQ(o.queries[0].latency_ns, 777);
  EXPECT_TRUE(o.queries[0].relevant);
  EXPECT_FALSE(o.queries[0].correct);
  EXPECT_EQ(o.queries[0].query_class, "inter");
  EXPECT_EQ(o.queries[0].hops, 0);  // present and zero: answered from its own store
  EXPECT_FALSE(o.queries[1].match_robot.has_value());
  EXPECT_FALSE(o.queries[1].match_frame.has_value());
  EXPECT_FALSE(o.queries[1].latency_ns.has_value());
  EXPECT_TRUE(o.queries[1].correct);
  EXPECT_EQ(o.queries[1].hops, 3);
  ASSERT_EQ(o.messages.size(), 1u);
  EXPECT_FALSE(o.messages[0].delivered_ns.has_value());
  EXPECT_EQ(o.messages[0].channel, "DVPR_QUERY_1");
  EXPECT_EQ(o.messages[0].type, "dvpr.query_t");
  EXPECT_EQ(o.messages[0].wire_bytes, 600);
  EXPECT_TRUE(o.messages[0].dropped);
  ASSERT_EQ(o.curves.size(), 1u);
  EXPECT_EQ(o.curves[0].label, std::string("centralized\0\n,", 14));
  EXPECT_EQ(o.curves[0].recall, (std::vector<double>{0.0, 0.5, 1.0}));
  EXPECT_EQ(o.curves[0].precision, (std::vector<double>{1.0, 0.75, 0.5}));
}

TEST(RankMessagesTest, RoleBytesFailoverAndBowRowsArrive) {
  RunOutput sent;
  RunResult r;
  RunRoleBytes roles;
  roles.copies[2] = CopyBytes{100, 200, 90, 180};  // verify_request
  roles.medium[5] = 77;                            // other
  r.roles = roles;
  r.duration_s = 45.5;
  sent.runs = {r};
  LinkRow link{Key(), 0, 1, 2, 3, 4, 5, RoleCopyBytes{}};
  (*link.roles)[0] = CopyBytes{1, 2, 3, 4};
  sent.links = {link};
  MessageRow m{Key(), 10, 20, 0, 1, "DVPR_VREQ_1", "dvpr.verification_request_t", 9, 10, false, "verify_request"};
  sent.messages = {m};
  sent.failover = {FailoverRow{Key(), 4, 22700000000, std::nullopt, 661, 12, 35}};
  BowRow bow;
  bow.key = Key();
  bow.partial_queries = 19;
  bow.mean_part_words = 14.25;
  bow.vote_not_centralized = 3;
  sent.bow = {bow};
  sent.bow_sizes = {BowSizeRow{Key(), 138, 7}};
  sent.connectivity = {ConnectivityRow{Key(), 300000000, 2, 1, 3, 4.0 / 3.0, 2, {1, 2, 1}}};

  const RunOutput o = DecodeOutput(EncodeOutput(0, sent)).output;
  ASSERT_EQ(o.runs.size(), 1u);
  ASSERT_TRUE(o.runs[0].roles.has_value());
  EXPECT_EQ(o.runs[0].roles->copies[2].delivered_wire, 180);
  EXPECT_EQ(o.runs[0].roles->copies[1].payload, 0);
  EXPECT_EQ(o.runs[0].roles->medium[5], 77);
  EXPECT_EQ(o.runs[0].duration_s, 45.5);
  ASSERT_EQ(o.links.size(), 1u);
  ASSERT_TRUE(o.links[0].roles.has_value());
  EXPECT_EQ((*o.links[0].roles)[0].delivered_payload, 3);
  ASSERT_EQ(o.messages.size(), 1u);
  EXPECT_EQ(o.messages[0].role, "verify_request");
  EXPECT_EQ(o.messages[0].delivered_ns, 20);
  ASSERT_EQ(o.failover.size(), 1u);
  EXPECT_EQ(o.failover[0].at_ns, 22700000000);
  EXPECT_FALSE(o.failover[0].detected_ns.has_value());
  EXPECT_EQ(o.failover[0].kept, 12);
  EXPECT_EQ(o.failover[0].incomplete_queries, 35);
  ASSERT_EQ(o.bow.size(), 1u);
  EXPECT_EQ(o.bow[0].partial_queries, 19);
  EXPECT_EQ(o.bow[0].mean_part_words, 14.25);
  EXPECT_EQ(o.bow[0].vote_not_centralized, 3);
  ASSERT_EQ(o.bow_sizes.size(), 1u);
  EXPECT_EQ(o.bow_sizes[0].payload_bytes, 138);
  EXPECT_EQ(o.bow_sizes[0].messages, 7);
  ASSERT_EQ(o.connectivity.size(), 1u);
  EXPECT_EQ(o.connectivity[0].time_ns, 300000000);
  EXPECT_EQ(o.connectivity[0].largest_component, 3);
  EXPECT_EQ(o.connectivity[0].robots_in_range, (std::vector<int>{1, 2, 1}));
  EXPECT_EQ(o.connectivity[0].mean_hops, 4.0 / 3.0);  // the double's bits, not a rounded text
  EXPECT_EQ(o.connectivity[0].max_hops, 2);
}

TEST(RankMessagesTest, EmptyOutputArrivesEmpty) {
  const IndexedOutput got = DecodeOutput(EncodeOutput(0, RunOutput{}));
  EXPECT_EQ(got.index, 0u);
  EXPECT_TRUE(got.output.runs.empty() && got.output.queries.empty() && got.output.curves.empty());
  // 8 bytes of index and an 8-byte count for each of the 13 row lists (runs, per_robot, links,
  // queries, messages, curves, failover, bow, bow_sizes, radio, medium, connectivity,
  // closure_pairs).
  EXPECT_EQ(EncodeOutput(0, RunOutput{}).size(), 8u * 14u);
}

TEST(RankMessagesTest, ShortOrLongMessagesAreRefused) {
  Bytes8 bytes = EncodeOutput(3, Sample());
  Bytes8 shorter(bytes.begin(), bytes.end() - 1);
  EXPECT_THROW(DecodeOutput(shorter), std::logic_error);
  bytes.push_back(std::byte{0});
  EXPECT_THROW(DecodeOutput(bytes), std::logic_error);
  // A count far past the end fails before anything is allocated for it.
  Bytes8 huge = EncodeOutput(0, RunOutput{});
  for (std::size_t i = 8; i < 16; ++i) huge[i] = std::byte{0x7f};
  EXPECT_THROW(DecodeOutput(huge), std::logic_error);
}

TEST(RankMessagesTest, FileArrivesWithItsBytes) {
  const std::string contents("\x93NUMPY\0\x01\xff", 10);
  const RunFile got = DecodeFile(EncodeFile(RunFile{"centroids/centroids_n3_r1.npy", contents}));
  EXPECT_EQ(got.path, "centroids/centroids_n3_r1.npy");
  EXPECT_EQ(got.contents, contents);
}

TEST(RankMessagesTest, FailureKeepsItsKindAndMessage) {
  const RankFailure input = DecodeFailure(EncodeFailure({FailureKind::kInput, "run paper n=2 run 0: x"}));
  EXPECT_EQ(input.kind, FailureKind::kInput);
  EXPECT_EQ(input.message, "run paper n=2 run 0: x");
  EXPECT_EQ(DecodeFailure(EncodeFailure({FailureKind::kInternal, ""})).kind, FailureKind::kInternal);
  Bytes8 unknown = EncodeFailure({FailureKind::kInput, "m"});
  unknown[0] = std::byte{7};
  EXPECT_THROW(DecodeFailure(unknown), std::logic_error);
}

}  // namespace
