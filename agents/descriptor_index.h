#pragma once
// The store a robot searches in the simulation: descriptors added one at a
// time as queries arrive, exact L2 search that skips the suppression window.
//
// Layout: one contiguous row-major float buffer (FAISS IndexFlatL2 style),
// grown geometrically, with squared norms cached so a search is one
// matrix-vector product: ||x - q||^2 = ||x||^2 - 2 x.q + ||q||^2, the same
// expansion the static protocol's batched distances use.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "agents/descriptors.h"
#include "agents/ids.h"

namespace dvpr {

struct IndexEntry {
  RobotId robot;  // robot that observed the frame
  FrameId frame;  // frame index in the full sequence
};

struct IndexMatch {
  RobotId robot;
  FrameId frame;
  float distance = 0.0f;  // squared L2
};

struct IndexSearchResult {
  std::optional<IndexMatch> best;  // none when nothing lies outside the window
  std::int64_t comparisons = 0;    // descriptors compared (the service-time cost)
};

class IncrementalIndex {
 public:
  explicit IncrementalIndex(int dim);

  int dim() const { return dim_; }
  std::size_t size() const { return entries_.size(); }

  void Add(RobotId robot, FrameId frame, const float* descriptor);

  // Best stored entry whose frame is more than `window` frames from
  // query_frame; ties go to the entry added first. Every stored entry counts
  // as a comparison.
  IndexSearchResult Search(const float* query, FrameId query_frame, int window) const;

  const std::vector<IndexEntry>& entries() const { return entries_; }
  // The stored descriptor of entry i (dim() floats), valid until the next Add or RemoveIf.
  const float* Descriptor(std::size_t i) const { return data_.data() + i * static_cast<std::size_t>(dim_); }

  // Removes every entry i with remove(i) true; the others keep their order, so ties in Search
  // still go to the entry added first. Re-clustering (agents/recluster/recluster_agent.h) moves stored
  // descriptors to their new owner with it.
  void RemoveIf(const std::function<bool(std::size_t)>& remove);

 private:
  int dim_;
  std::vector<float> data_;   // size() x dim, row-major
  std::vector<float> norms_;  // squared norms of the rows
  std::vector<IndexEntry> entries_;
  mutable std::vector<float> scratch_;
};

}  // namespace dvpr
