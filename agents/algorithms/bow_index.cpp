#include "agents/algorithms/bow_index.h"

#include <algorithm>
#include <cstdlib>

namespace dvpr {

void BowIndex::Add(RobotId robot, FrameId frame, const BowVector& part) {
  if (frame.value < 0 || !observer_.emplace(frame.value, robot).second) return;
  for (const BowEntry& e : part) postings_[e.word].push_back({frame.value, e.weight});
  postings_count_ += static_cast<std::int64_t>(part.size());
  if (static_cast<std::size_t>(frame.value) >= sums_.size()) sums_.resize(static_cast<std::size_t>(frame.value) + 1, 0.0);
}

BowSearchResult BowIndex::Search(const BowVector& part, FrameId query, const FrameWindow& window) const {
  BowSearchResult result;
  const FrameInterval skip = window.Around(query.value);
  touched_.clear();
  for (const BowEntry& q : part) {
    const auto it = postings_.find(q.word);
    if (it == postings_.end()) continue;
    for (const Posting& p : it->second) {
      if (skip.Contains(p.frame)) continue;
      ++result.comparisons;
      double& sum = sums_[static_cast<std::size_t>(p.frame)];
      if (sum == 0.0) touched_.push_back(p.frame);
      sum += std::min(static_cast<double>(q.weight), static_cast<double>(p.weight));
    }
  }
  std::int32_t best_frame = -1;
  double best_score = 0.0;
  for (const std::int32_t f : touched_) {
    double& sum = sums_[static_cast<std::size_t>(f)];
    if (sum > best_score || (sum == best_score && f < best_frame)) best_frame = f, best_score = sum;
    sum = 0.0;
  }
  if (best_frame >= 0) result.best = BowIndexMatch{observer_.at(best_frame), FrameId(best_frame), best_score};
  return result;
}

}  // namespace dvpr
