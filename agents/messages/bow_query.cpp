#include "agents/messages/bow_query.h"

#include "agents/messages/lcm_codec.h"

namespace dvpr {

bow_query_t MakeBowQuery(RobotId robot, FrameId frame, const BowVector& part, SimTime sent) {
  bow_query_t q;
  q.utime = sent.ns() / 1000;
  q.robot = static_cast<std::int16_t>(robot.value);
  q.frame = frame.value;
  q.count = static_cast<std::int32_t>(part.size());
  q.words.reserve(part.size());
  q.weights.reserve(part.size());
  for (const BowEntry& e : part) {
    q.words.push_back(e.word);
    q.weights.push_back(e.weight);
  }
  return q;
}

BowVector BowPartOf(const bow_query_t& q) {
  BowVector v;
  v.reserve(q.words.size());
  for (std::size_t i = 0; i < q.words.size() && i < q.weights.size(); ++i) v.push_back({q.words[i], q.weights[i]});
  return v;
}

std::int64_t EncodedBowQueryBytes(const BowVector& part) {
  return static_cast<std::int64_t>(Encode(MakeBowQuery(RobotId(0), FrameId(0), part, SimTime())).size());
}

std::int64_t EncodedDescriptorQueryBytes(int dim) {
  query_t q;
  q.dim = static_cast<std::int16_t>(dim);
  q.descriptor.assign(static_cast<std::size_t>(dim), 0.0f);
  return static_cast<std::int64_t>(Encode(q).size());
}

}  // namespace dvpr
