// Round trips and encoded sizes of dvpr's LCM messages.
// Expected sizes are worked out by hand from LCM's encoding rules: an 8-byte
// type fingerprint, then each field big-endian at its natural width
// (int64 8, int32 4, int16 2, boolean 1, float 4, byte 1), arrays without
// padding, their length taken from an earlier field.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "agents/lcm_codec.h"

namespace dvpr {
namespace {

query_t MakeQuery(int dim) {
  query_t q;
  q.utime = 1234567;
  q.robot = 7;
  q.frame = 4540;
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

TEST(MessageSize, QueryWith128FloatsIs536Bytes) {
  // fingerprint 8 + utime 8 + robot 2 + frame 4 + dim 2 + 128 x 4 = 536
  EXPECT_EQ(Encode(MakeQuery(128)).size(), 536u);
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
  q[22] = 0x80;  // dim = -32768 + ...: negative
  EXPECT_FALSE(Decode<query_t>(q).has_value());
}

}  // namespace
}  // namespace dvpr
