// Recycled payload buffers (net_models/core/payload_buffers.h): by size class, bounded, and given
// back by the network when a payload's last copy is delivered or dropped.
#include "net_models/core/payload_buffers.h"

#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "net_models/medium/ideal_link.h"
#include "net_models/network/network.h"
#include "sim/simulator.h"

namespace dvpr {
namespace {

std::vector<std::uint8_t> Buffer(std::size_t capacity) {
  std::vector<std::uint8_t> b;
  b.reserve(capacity);
  return b;
}

TEST(PayloadBuffers, TakesAKeptBufferLargeEnoughOrNone) {
  PayloadBuffers pool;
  EXPECT_EQ(pool.Take(35).capacity(), 0u);  // nothing kept yet
  pool.Give(Buffer(544));                    // class 9: [512, 1024)
  EXPECT_EQ(pool.Take(17).capacity(), 0u);   // class 4: 5..8 are empty, 9 is more than 4 up
  pool.Give(Buffer(40));                     // class 5: [32, 64)
  EXPECT_EQ(pool.Kept(), 2u);
  EXPECT_EQ(pool.Take(600).capacity(), 0u);    // class 9 holds only 544 < 600, 10..13 are empty
  EXPECT_EQ(pool.Take(50).capacity(), 544u);   // class 5 holds only 40 < 50; 9 is 4 classes up
  EXPECT_EQ(pool.Take(35).capacity(), 40u);    // its own class, large enough
  EXPECT_EQ(pool.Kept(), 0u);
}

TEST(PayloadBuffers, KeepsAtMostItsBoundsAndNoEmptyBuffer) {
  PayloadBuffers pool;
  pool.Give(std::vector<std::uint8_t>());
  pool.Give(Buffer(PayloadBuffers::kMaxKept + 1));
  EXPECT_EQ(pool.Kept(), 0u);
  pool.Give(Buffer(PayloadBuffers::kMaxKept));
  EXPECT_EQ(pool.Kept(), 1u);
  // 100 bytes: class 6 ([64, 128)) keeps 2^20 / 2^6 = 16 384 (more than kPerClass, 1024).
  static_assert(PayloadBuffers::kPerClass == 1024 && PayloadBuffers::kClassBytes == std::size_t{1} << 20);
  for (int i = 0; i < 16384 + 5; ++i) pool.Give(Buffer(100));
  EXPECT_EQ(pool.Kept(), 1u + 16384u);
  // 5000 bytes: class 12 ([4096, 8192)) keeps kPerClass (2^20 / 2^12 = 256 is fewer).
  for (int i = 0; i < 1024 + 5; ++i) pool.Give(Buffer(5000));
  EXPECT_EQ(pool.Kept(), 1u + 16384u + 1024u);
  EXPECT_EQ(pool.Take(0).capacity(), 0u);
  EXPECT_EQ(pool.Take(PayloadBuffers::kMaxKept + 1).capacity(), 0u);
}

// 64 MiB in all: 64 buffers of 1 MiB (class 20) fill it, a 65th is freed, and a small buffer no
// longer fits either until one is taken out again.
TEST(PayloadBuffers, KeepsAtMostItsByteBudget) {
  static_assert(PayloadBuffers::kMaxKeptBytes == std::size_t{64} << 20);
  PayloadBuffers pool;
  for (int i = 0; i < 65; ++i) pool.Give(Buffer(std::size_t{1} << 20));
  EXPECT_EQ(pool.Kept(), 64u);
  pool.Give(Buffer(100));
  EXPECT_EQ(pool.Kept(), 64u);
  EXPECT_EQ(pool.Take(std::size_t{1} << 20).capacity(), std::size_t{1} << 20);
  pool.Give(Buffer(100));  // 63 MiB + 100 bytes
  EXPECT_EQ(pool.Kept(), 64u);
  EXPECT_EQ(pool.Take(100).capacity(), 100u);
}

TEST(PayloadBuffers, TheNetworkGivesAPayloadBackAfterItsLastCopy) {
  Simulator sim;
  Network net(sim, 3, std::make_unique<IdealLink>());
  const ChannelId all = net.InternChannel("ALL");
  const MessageTypeId type = net.InternType("t");
  for (int n = 0; n < 3; ++n) net.Join(NodeId(n), all);
  std::vector<std::uint8_t> payload(100, 7);
  const std::uint8_t* data = payload.data();
  EXPECT_EQ(net.Send(NodeId(0), all, type, std::move(payload)), 2u);
  sim.Run();  // both copies delivered: the one buffer is kept
  EXPECT_EQ(net.payload_buffers().Kept(), 1u);
  const std::vector<std::uint8_t> again = net.payload_buffers().Take(100);
  EXPECT_EQ(again.data(), data);
}

}  // namespace
}  // namespace dvpr
