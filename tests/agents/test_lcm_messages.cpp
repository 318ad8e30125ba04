// Round trips and encoded sizes of dvpr's LCM messages.
// Expected sizes are worked out by hand from LCM's encoding rules: an 8-byte
// type fingerprint, then each field big-endian at its natural width
// (int64 8, int32 4, int16 2, boolean 1, float 4, byte 1), arrays without
// padding, their length taken from an earlier field.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <span>
#include <vector>

#include "agents/messages/lcm_codec.h"

namespace dvpr {
namespace {

query_t MakeQuery(int dim) {
  query_t q;
  q.utime = 1234567;
  q.robot = 7;
  q.frame = 4540;
  q.capture_utime = 1317643200000000;
  q.dim = static_cast<std::int16_t>(dim);
  q.descriptor.resize(dim);
  for (int i = 0; i < dim; ++i) q.descriptor[i] = 0.25f * static_cast<float>(i) - 3.0f;
  return q;
}

verify_request_t MakeVerifyRequest(int payload) {
  verify_request_t r;
  r.utime = 99;
  r.query_robot = 1;
  r.query_frame = 2;
  r.match_robot = 3;
  r.match_frame = 4;
  r.payload_size = payload;
  r.payload.resize(payload);
  for (int i = 0; i < payload; ++i) r.payload[i] = static_cast<std::uint8_t>(i * 31);
  return r;
}

match_t MakeMatch() {
  match_t m;
  m.utime = -5;  // int64 sign survives
  m.query_robot = 19;
  m.query_frame = 100000;
  m.responder = 3;
  m.has_match = true;
  m.match_robot = 2;
  m.match_frame = 17;
  m.distance = 0.123f;
  return m;
}

verify_result_t MakeVerifyResult() {
  verify_result_t v;
  v.utime = 42;
  v.query_robot = 1;
  v.query_frame = 2;
  v.match_robot = 3;
  v.match_frame = 4;
  v.accepted = true;
  v.inliers = 57;
  return v;
}

TEST(MessageSize, QueryWith128FloatsIs544Bytes) {
  // fingerprint 8 + utime 8 + robot 2 + frame 4 + capture_utime 8 + dim 2 + 128 x 4 = 544
  EXPECT_EQ(Encode(MakeQuery(128)).size(), 544u);
}

TEST(MessageSize, MatchIs35Bytes) {
  // 8 + utime 8 + query_robot 2 + query_frame 4 + responder 2 + has_match 1
  //   + match_robot 2 + match_frame 4 + distance 4 = 35
  EXPECT_EQ(Encode(MakeMatch()).size(), 35u);
}

TEST(MessageSize, VerifyRequestIs32BytesPlusPayload) {
  // 8 + 8 + 2 + 4 + 2 + 4 + payload_size 4 = 32, then the payload
  EXPECT_EQ(Encode(MakeVerifyRequest(0)).size(), 32u);
  EXPECT_EQ(Encode(MakeVerifyRequest(25000)).size(), 25032u);
}

// Re-clustering messages (agents/recluster/recluster_messages.h, whose size functions are
// pinned against these in tests/agents/recluster/).
descriptor_batch_t MakeBatch(int count, int dim) {
  descriptor_batch_t b;
  b.utime = 5;
  b.epoch = 3;
  b.sender = 2;
  b.count = count;
  b.dim = static_cast<std::int16_t>(dim);
  for (int i = 0; i < count; ++i) {
    b.robots.push_back(static_cast<std::int16_t>(i % 3));
    b.frames.push_back(1000 + i);
    std::vector<float> row;
    for (int c = 0; c < dim; ++c) row.push_back(static_cast<float>(i) - 0.5f * static_cast<float>(c));
    b.descriptors.push_back(row);
  }
  return b;
}

centroid_table_t MakeTable(int k, int dim) {
  centroid_table_t t;
  t.utime = 7;
  t.epoch = 2;
  t.leader = 0;
  t.k = static_cast<std::int16_t>(k);
  t.dim = static_cast<std::int16_t>(dim);
  for (int c = 0; c < k; ++c) {
    t.centroids.emplace_back(static_cast<std::size_t>(dim), 0.25f * static_cast<float>(c));
    t.owners.push_back(static_cast<std::int16_t>(c % 4));
  }
  return t;
}

TEST(MessageSize, DescriptorBatchIs28BytesPlus6Plus4DimPerDescriptor) {
  // 8 + utime 8 + epoch 4 + sender 2 + count 4 + dim 2 = 28; each descriptor: robot 2 + frame 4
  // + dim x 4. Empty: 28; one of dim 1: 38; two of dim 1: 48; three of 128 floats:
  // 28 + 3 x (6 + 512) = 1582.
  EXPECT_EQ(Encode(MakeBatch(0, 128)).size(), 28u);
  EXPECT_EQ(Encode(MakeBatch(1, 1)).size(), 38u);
  EXPECT_EQ(Encode(MakeBatch(2, 1)).size(), 48u);
  EXPECT_EQ(Encode(MakeBatch(3, 128)).size(), 1582u);
}

TEST(MessageSize, CentroidTableIs26BytesPlus4DimPlus2PerCentroid) {
  // 8 + utime 8 + epoch 4 + leader 2 + k 2 + dim 2 = 26; each centroid dim x 4 + owner 2.
  // k = 2, dim 1: 26 + 2 x 6 = 38; k = 40, dim 128: 26 + 40 x 514 = 20586.
  EXPECT_EQ(Encode(MakeTable(2, 1)).size(), 38u);
  EXPECT_EQ(Encode(MakeTable(40, 128)).size(), 20586u);
}

TEST(MessageSize, VerifyResultIs33Bytes) {
  // 8 + 8 + 2 + 4 + 2 + 4 + accepted 1 + inliers 4 = 33
  EXPECT_EQ(Encode(MakeVerifyResult()).size(), 33u);
}

template <typename Msg>
Msg RoundTrip(const Msg& in) {
  const auto bytes = Encode(in);
  const auto out = Decode<Msg>(bytes);
  EXPECT_TRUE(out.has_value());
  return out.value_or(Msg{});
}

TEST(MessageRoundTrip, QueryEmptyTypicalAndMaximal) {
  for (int dim : {0, 1, 128, 4096, 32767}) {
    const query_t in = MakeQuery(dim);
    const query_t out = RoundTrip(in);
    EXPECT_EQ(out.utime, in.utime);
    EXPECT_EQ(out.robot, in.robot);
    EXPECT_EQ(out.frame, in.frame);
    EXPECT_EQ(out.capture_utime, in.capture_utime);
    EXPECT_EQ(out.dim, dim);
    EXPECT_EQ(out.descriptor, in.descriptor) << "dim " << dim;
  }
}

TEST(MessageRoundTrip, MatchWithAndWithoutMatch) {
  match_t in = MakeMatch();
  match_t out = RoundTrip(in);
  EXPECT_EQ(out.utime, -5);
  EXPECT_EQ(out.query_robot, 19);
  EXPECT_EQ(out.query_frame, 100000);
  EXPECT_EQ(out.responder, 3);
  EXPECT_TRUE(out.has_match);
  EXPECT_EQ(out.match_robot, 2);
  EXPECT_EQ(out.match_frame, 17);
  EXPECT_FLOAT_EQ(out.distance, 0.123f);
  in.has_match = false;
  EXPECT_FALSE(RoundTrip(in).has_match);
}

TEST(MessageRoundTrip, VerifyRequestEmptyAndLargePayload) {
  for (int payload : {0, 25000, 1 << 22}) {
    const verify_request_t in = MakeVerifyRequest(payload);
    const verify_request_t out = RoundTrip(in);
    EXPECT_EQ(out.payload_size, payload);
    EXPECT_EQ(out.payload, in.payload);
    EXPECT_EQ(out.match_frame, 4);
  }
}

TEST(MessageRoundTrip, VerifyResult) {
  const verify_result_t out = RoundTrip(MakeVerifyResult());
  EXPECT_TRUE(out.accepted);
  EXPECT_EQ(out.inliers, 57);
  EXPECT_EQ(out.query_frame, 2);
}

// DecodeInto reuses the message it is given: a later message leaves nothing of an earlier one,
// also where the generated decoder skips an empty array (dim 0, payload_size 0).
TEST(MessageDecodeInto, ALaterMessageReplacesAllOfAnEarlierOne) {
  query_t q;
  ASSERT_TRUE(DecodeInto(Encode(MakeQuery(3)), q));
  EXPECT_EQ(q.descriptor, (std::vector<float>{-3.0f, -2.75f, -2.5f}));
  query_t empty = MakeQuery(0);
  empty.frame = 12;
  ASSERT_TRUE(DecodeInto(Encode(empty), q));
  EXPECT_EQ(q.dim, 0);
  EXPECT_TRUE(q.descriptor.empty());
  EXPECT_EQ(q.frame, 12);
  ASSERT_TRUE(DecodeInto(Encode(MakeQuery(2)), q));
  EXPECT_EQ(q.descriptor, (std::vector<float>{-3.0f, -2.75f}));

  verify_request_t r;
  ASSERT_TRUE(DecodeInto(Encode(MakeVerifyRequest(4)), r));
  EXPECT_EQ(r.payload, (std::vector<std::uint8_t>{0, 31, 62, 93}));
  ASSERT_TRUE(DecodeInto(Encode(MakeVerifyRequest(0)), r));
  EXPECT_TRUE(r.payload.empty());

  match_t m;
  ASSERT_TRUE(DecodeInto(Encode(MakeMatch()), m));
  EXPECT_EQ(m.query_frame, 100000);
  EXPECT_FALSE(DecodeInto(Encode(MakeVerifyResult()), m));  // another type: rejected
}

template <typename Msg>
void ExpectEveryTruncationFails(const Msg& msg) {
  const auto bytes = Encode(msg);
  for (std::size_t len = 0; len < bytes.size(); ++len) {
    EXPECT_FALSE(Decode<Msg>(std::span(bytes.data(), len)).has_value())
        << Msg::getTypeName() << " truncated to " << len << " of " << bytes.size();
  }
}

TEST(MessageDecode, TruncatedBufferFailsCleanly) {
  ExpectEveryTruncationFails(MakeQuery(128));
  ExpectEveryTruncationFails(MakeMatch());
  ExpectEveryTruncationFails(MakeVerifyRequest(300));
  ExpectEveryTruncationFails(MakeVerifyResult());
}

TEST(MessageDecode, TrailingBytesAreRejected) {
  auto bytes = Encode(MakeMatch());
  bytes.push_back(0);
  EXPECT_FALSE(Decode<match_t>(bytes).has_value());
}

TEST(MessageDecode, WrongTypeIsRejectedByFingerprint) {
  const auto bytes = Encode(MakeVerifyResult());
  EXPECT_FALSE(Decode<match_t>(bytes).has_value());
  EXPECT_FALSE(Decode<query_t>(bytes).has_value());
}

TEST(MessageDecode, GarbageLengthFieldDoesNotAllocate) {
  // A valid fingerprint followed by a length field claiming 2^31-1 bytes.
  auto bytes = Encode(MakeVerifyRequest(8));
  const std::size_t size_offset = 28;
  bytes[size_offset] = 0x7f;
  bytes[size_offset + 1] = bytes[size_offset + 2] = bytes[size_offset + 3] = 0xff;
  EXPECT_FALSE(Decode<verify_request_t>(bytes).has_value());
  auto q = Encode(MakeQuery(4));
  q[30] = 0x80;  // dim (after fingerprint 8, utime 8, robot 2, frame 4, capture_utime 8) negative
  EXPECT_FALSE(Decode<query_t>(q).has_value());
}

// `bytes` truncated at every length (the whole encoding included), with a trailing byte, and with
// each byte of the 8-byte fingerprint flipped, appended to `buffers`.
void AppendDamagedCopies(const std::vector<std::uint8_t>& bytes, std::vector<std::vector<std::uint8_t>>& buffers) {
  for (std::size_t len = 0; len <= bytes.size(); ++len) buffers.emplace_back(bytes.begin(), bytes.begin() + len);
  buffers.push_back(bytes);
  buffers.back().push_back(0);
  for (std::size_t i = 0; i < 8; ++i) {
    buffers.push_back(bytes);
    buffers.back()[i] ^= 0x01;
  }
}

// DecodeInto<query_t> has a decoder of its own (lcm_codec.h); LCM's generated decoder, called
// here directly on a fresh message, is the reference: for every buffer both accept or both
// reject, and what they accept decodes to the same fields and the same float bits (NaNs,
// negative zero and denormals included). Buffers: encodings of several dims, each truncated at
// every length, with a trailing byte, with each byte of the fingerprint flipped, and with the
// dim field set to values that claim more or fewer floats than the buffer holds.
TEST(MessageDecodeInto, QueryDecoderAgreesWithTheGeneratedOneOnEveryBuffer) {
  std::vector<std::vector<std::uint8_t>> buffers;
  for (int dim : {0, 1, 3, 8, 128}) {
    query_t q = MakeQuery(dim);
    if (dim >= 3) {
      q.descriptor[0] = std::bit_cast<float>(0x7fc00001u);  // a NaN with a payload
      q.descriptor[1] = -0.0f;
      q.descriptor[2] = std::bit_cast<float>(0x00000001u);  // the smallest denormal
    }
    q.robot = -2;
    q.frame = -70000;
    const auto bytes = Encode(q);
    AppendDamagedCopies(bytes, buffers);
    for (const std::uint16_t claimed : {0, 1, 2, 127, 129, 0x7fff, 0x8000, 0xffff}) {
      buffers.push_back(bytes);
      buffers.back()[30] = static_cast<std::uint8_t>(claimed >> 8);
      buffers.back()[31] = static_cast<std::uint8_t>(claimed & 0xff);
    }
  }
  int accepted = 0;
  for (const auto& buf : buffers) {
    query_t reference;
    const auto dim = buf.size() >= 32 ? static_cast<std::int16_t>(buf[30] << 8 | buf[31]) : std::int16_t{0};
    // The generated decoder resizes before it checks the length: only give it dims >= 0.
    const bool ok_reference =
        dim >= 0 && reference.decode(buf.data(), 0, static_cast<int>(buf.size())) == static_cast<int>(buf.size());
    query_t fast;
    fast.descriptor.assign(5, 9.0f);  // left from an earlier message
    const bool ok_fast = DecodeInto(std::span<const std::uint8_t>(buf), fast);
    ASSERT_EQ(ok_fast, ok_reference) << "buffer of " << buf.size() << " bytes";
    if (!ok_fast) continue;
    ++accepted;
    EXPECT_EQ(fast.utime, reference.utime);
    EXPECT_EQ(fast.robot, reference.robot);
    EXPECT_EQ(fast.frame, reference.frame);
    EXPECT_EQ(fast.capture_utime, reference.capture_utime);
    ASSERT_EQ(fast.dim, reference.dim);
    ASSERT_EQ(fast.descriptor.size(), static_cast<std::size_t>(reference.dim));
    for (std::size_t i = 0; i < fast.descriptor.size(); ++i) {
      EXPECT_EQ(std::bit_cast<std::uint32_t>(fast.descriptor[i]), std::bit_cast<std::uint32_t>(reference.descriptor[i]));
    }
  }
  // Each dim's whole encoding, and the one whose dim field was set to its own value (0 and 1
  // for dims 0 and 1; 127 and 129 fit no buffer).
  EXPECT_EQ(accepted, 5 + 2);
}

// DecodeInto<match_t> has a decoder of its own too; the generated one is the reference, as above.
// Buffers: two replies (with a match: a NaN distance with a payload, a negative has_match byte;
// without one: -0 distance), each truncated at every length, with a trailing byte, and with each
// byte of the fingerprint flipped.
TEST(MessageDecodeInto, MatchDecoderAgreesWithTheGeneratedOneOnEveryBuffer) {
  match_t with{};
  with.utime = -1234567890123;
  with.query_robot = -3;
  with.query_frame = 70001;
  with.responder = 513;
  with.has_match = -1;
  with.match_robot = 258;
  with.match_frame = -5;
  with.distance = std::bit_cast<float>(0x7fc00001u);
  match_t without{};
  without.utime = 42;
  without.match_robot = -1;
  without.match_frame = -1;
  without.distance = -0.0f;
  std::vector<std::vector<std::uint8_t>> buffers;
  for (const match_t& m : {with, without}) {
    const auto bytes = Encode(m);
    ASSERT_EQ(bytes.size(), 35u);  // 8 + 8 + 2 + 4 + 2 + 1 + 2 + 4 + 4, worked by hand
    AppendDamagedCopies(bytes, buffers);
  }
  int accepted = 0;
  for (const auto& buf : buffers) {
    match_t reference{};
    const bool ok_reference = reference.decode(buf.data(), 0, static_cast<int>(buf.size())) == static_cast<int>(buf.size());
    match_t fast{};
    fast.utime = 99;  // left from an earlier message
    const bool ok_fast = DecodeInto(std::span<const std::uint8_t>(buf), fast);
    ASSERT_EQ(ok_fast, ok_reference) << "buffer of " << buf.size() << " bytes";
    if (!ok_fast) continue;
    ++accepted;
    EXPECT_EQ(fast.utime, reference.utime);
    EXPECT_EQ(fast.query_robot, reference.query_robot);
    EXPECT_EQ(fast.query_frame, reference.query_frame);
    EXPECT_EQ(fast.responder, reference.responder);
    EXPECT_EQ(fast.has_match, reference.has_match);
    EXPECT_EQ(fast.match_robot, reference.match_robot);
    EXPECT_EQ(fast.match_frame, reference.match_frame);
    EXPECT_EQ(std::bit_cast<std::uint32_t>(fast.distance), std::bit_cast<std::uint32_t>(reference.distance));
  }
  EXPECT_EQ(accepted, 2);  // each whole encoding, nothing else
  EXPECT_EQ(Decode<match_t>(Encode(with))->query_frame, 70001);
}

TEST(MessageRoundTrip, DescriptorBatchAndCentroidTable) {
  const descriptor_batch_t b = MakeBatch(3, 5);
  const descriptor_batch_t b2 = RoundTrip(b);
  EXPECT_EQ(b2.epoch, 3);
  EXPECT_EQ(b2.sender, 2);
  EXPECT_EQ(b2.frames, b.frames);
  EXPECT_EQ(b2.robots, b.robots);
  EXPECT_EQ(b2.descriptors, b.descriptors);
  const centroid_table_t t = MakeTable(3, 4);
  const centroid_table_t t2 = RoundTrip(t);
  EXPECT_EQ(t2.epoch, 2);
  EXPECT_EQ(t2.centroids, t.centroids);
  EXPECT_EQ(t2.owners, t.owners);
  ExpectEveryTruncationFails(MakeBatch(2, 3));
  ExpectEveryTruncationFails(MakeTable(2, 3));
}

TEST(MessageDecode, ReclusteringLengthFieldsThatClaimTooMuchAreRejected) {
  auto b = Encode(MakeBatch(1, 2));
  b[22] = 0x7f;  // count (offset 8 + 8 + 4 + 2) = 2^31 - ...: far more rows than bytes
  EXPECT_FALSE(Decode<descriptor_batch_t>(b).has_value());
  auto t = Encode(MakeTable(1, 2));
  t[24] = 0x7f;  // dim (offset 8 + 8 + 4 + 2 + 2): 32k floats per centroid
  EXPECT_FALSE(Decode<centroid_table_t>(t).has_value());
}

}  // namespace
}  // namespace dvpr
