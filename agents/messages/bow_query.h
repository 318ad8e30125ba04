#pragma once
// The partial query of the distributed inverted index as an LCM message (bow_query_t,
// lcmtypes/dvpr/bow_query_t.lcm): what a robot sends for one frame to the owner of some of its
// words. Its encoded size, 8 (fingerprint) + 8 (utime) + 2 (robot) + 4 (frame) + 4 (count)
// + count x (4 + 4) bytes, is what the protocols count.
#include <cstdint>

#include <dvpr/bow_query_t.hpp>

#include "agents/algorithms/bow_vector.h"
#include "agents/algorithms/ids.h"
#include "sim/sim_time.h"

namespace dvpr {

bow_query_t MakeBowQuery(RobotId robot, FrameId frame, const BowVector& part, SimTime sent);
BowVector BowPartOf(const bow_query_t& q);
// Bytes of Encode(MakeBowQuery(...)) for `part`: the message is encoded and measured.
std::int64_t EncodedBowQueryBytes(const BowVector& part);
// Bytes of an encoded query_t carrying a `dim`-value descriptor: the global-descriptor query the
// BoW comparison sets beside the partial queries (docs/bow.md).
std::int64_t EncodedDescriptorQueryBytes(int dim);

}  // namespace dvpr
