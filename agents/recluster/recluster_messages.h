#pragma once
// The messages of adaptive re-clustering (agents/recluster/recluster_agent.h): their channels
// and LCM-encoded sizes. The static protocol counts its re-clustering bytes with the sizes.
#include <cstdint>
#include <string>

#include "agents/algorithms/ids.h"
#include "lcmtypes/channels/channels.h"

namespace dvpr {

namespace channels {
// Each robot's sample for an epoch, to the leader (descriptor_batch_t).
inline std::string Sample(RobotId leader) { return ChannelName(ChannelKind::kSample, leader.value); }
// Stored descriptors moved to their owner under a new table (descriptor_batch_t).
inline std::string Migrate(RobotId dst) { return ChannelName(ChannelKind::kMigrate, dst.value); }
// The leader's table of an epoch, to every robot (centroid_table_t).
inline const std::string kTable = ChannelName(ChannelKind::kTable);
}  // namespace channels

// LCM-encoded sizes (fingerprint included), worked out from LCM's rules and pinned against
// Encode() in tests/agents/recluster/test_recluster_messages.cpp.
// descriptor_batch_t: 8 + utime 8 + epoch 4 + sender 2 + count 4 + dim 2 = 28, then per
// descriptor robot 2 + frame 4 + dim floats.
inline std::int64_t DescriptorBatchBytes(std::int64_t count, int dim) { return 28 + count * (6 + 4 * std::int64_t{dim}); }
// centroid_table_t: 8 + utime 8 + epoch 4 + leader 2 + k 2 + dim 2 = 26, then k x dim floats and
// k int16 owners.
inline std::int64_t CentroidTableBytes(int k, int dim) { return 26 + std::int64_t{k} * (4 * std::int64_t{dim} + 2); }

}  // namespace dvpr
