// The re-clustering messages' channels and the sizes the static protocol counts its bytes with,
// against LCM's own encoding. Sizes worked out by hand from LCM's rules: an 8-byte fingerprint,
// then each field big-endian at its width, arrays without padding.
#include <cstdint>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "agents/messages/lcm_codec.h"
#include "agents/recluster/recluster_messages.h"

namespace dvpr {
namespace {

descriptor_batch_t Batch(int count, int dim) {
  descriptor_batch_t b{};
  b.count = count;
  b.dim = static_cast<std::int16_t>(dim);
  b.robots.assign(static_cast<std::size_t>(count), 1);
  b.frames.assign(static_cast<std::size_t>(count), 7);
  b.descriptors.assign(static_cast<std::size_t>(count), std::vector<float>(static_cast<std::size_t>(dim), 0.5f));
  return b;
}

centroid_table_t Table(int k, int dim) {
  centroid_table_t t{};
  t.k = static_cast<std::int16_t>(k);
  t.dim = static_cast<std::int16_t>(dim);
  t.centroids.assign(static_cast<std::size_t>(k), std::vector<float>(static_cast<std::size_t>(dim), 0.25f));
  t.owners.assign(static_cast<std::size_t>(k), 0);
  return t;
}

TEST(ReclusterMessages, DescriptorBatchBytesIs28Plus6Plus4DimPerDescriptor) {
  // 28 header bytes; per descriptor robot 2 + frame 4 + 4 x dim.
  EXPECT_EQ(DescriptorBatchBytes(0, 128), 28);
  EXPECT_EQ(DescriptorBatchBytes(1, 1), 38);
  EXPECT_EQ(DescriptorBatchBytes(3, 128), 1582);  // 28 + 3 x 518
  for (const auto& [count, dim] : {std::pair{0, 128}, std::pair{1, 1}, std::pair{3, 128}, std::pair{5, 16}}) {
    EXPECT_EQ(static_cast<std::int64_t>(Encode(Batch(count, dim)).size()), DescriptorBatchBytes(count, dim))
        << count << " x " << dim;
  }
}

TEST(ReclusterMessages, CentroidTableBytesIs26Plus4DimPlus2PerCentroid) {
  EXPECT_EQ(CentroidTableBytes(2, 1), 38);         // 26 + 2 x 6
  EXPECT_EQ(CentroidTableBytes(40, 128), 20586);   // 26 + 40 x 514
  for (const auto& [k, dim] : {std::pair{1, 1}, std::pair{2, 1}, std::pair{40, 128}}) {
    EXPECT_EQ(static_cast<std::int64_t>(Encode(Table(k, dim)).size()), CentroidTableBytes(k, dim)) << k << " x " << dim;
  }
}

TEST(ReclusterMessages, ChannelsNameTheirDestination) {
  EXPECT_EQ(channels::Sample(RobotId(0)), "DVPR_SAMPLE_0");
  EXPECT_EQ(channels::Migrate(RobotId(12)), "DVPR_MIGRATE_12");
  EXPECT_EQ(channels::kTable, "DVPR_TABLE");
}

}  // namespace
}  // namespace dvpr
