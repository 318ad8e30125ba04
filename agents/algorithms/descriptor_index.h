#pragma once
// The store a robot searches in the simulation: descriptors added one at a
// time as queries arrive, exact L2 search that skips the suppression window.
//
// Layout: one contiguous row-major float buffer (FAISS IndexFlatL2 style),
// grown geometrically, with squared norms cached. The model's search is one
// matrix-vector product: ||x - q||^2 = ||x||^2 - 2 x.q + ||q||^2, the same
// expansion the static protocol's batched distances use (SearchFullScan).
// Search gives the same entry and the same float distance, bit for bit, but
// computes the model's value only for the few rows that could win: a screen
// keeps every row again in half precision and rules most rows out from lower
// bounds over their leading values (agents/algorithms/half_screen.h); the rows that pass
// every bound get the full product's own value (agents/algorithms/gemv_row.h).
// docs/performance.md.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "agents/algorithms/descriptors.h"
#include "agents/algorithms/half_screen.h"
#include "agents/algorithms/ids.h"
#include "agents/algorithms/index.h"

namespace dvpr {

struct IndexMatch {
  RobotId robot;
  FrameId frame;
  float distance = 0.0f;  // squared L2
};

// comparisons: descriptors compared (the service-time cost); best: none when nothing lies outside
// the window.
using IndexSearchResult = SearchResult<IndexMatch>;

class IncrementalIndex final : public Index<const float*, IndexMatch> {
 public:
  explicit IncrementalIndex(int dim);

  int dim() const override { return dim_; }
  std::size_t size() const override { return entries_.size(); }

  void Add(RobotId robot, FrameId frame, const float* descriptor) override;

  // Best stored entry whose frame is outside query_frame's suppression window (frame_window.h);
  // ties go to the entry added first. Every stored entry counts
  // as a comparison (the model's cost, however few rows the search reads).
  IndexSearchResult Search(const float* query, FrameId query_frame, const FrameWindow& window) const override;
  // The same answer from the full matrix-vector product over every row: the
  // definition Search is tested against, and the benchmarks' baseline.
  IndexSearchResult SearchFullScan(const float* query, FrameId query_frame, const FrameWindow& window) const;

  const std::vector<IndexEntry>& entries() const { return entries_; }
  // Counts the calls that changed what is stored (Add, RemoveIf): a search's result still holds
  // while this is what it was (a robot searches its queued queries ahead, RobotAgent).
  std::uint64_t changes() const { return changes_; }
  // The stored descriptor of entry i (dim() floats), valid until the next Add or RemoveIf.
  const float* Descriptor(std::size_t i) const { return data_.data() + i * static_cast<std::size_t>(dim_); }

  // Removes every entry i with remove(i) true; the others keep their order, so ties in Search
  // still go to the entry added first. Re-clustering (agents/recluster/recluster_agent.h) moves stored
  // descriptors to their new owner with it.
  void RemoveIf(const std::function<bool(std::size_t)>& remove);

 private:
  // Row i's distance to the query as SearchFullScan computes it, bit for bit.
  float ModelDistance(std::size_t i, const float* query, float q_norm) const;
  IndexMatch Match(std::size_t i, float distance) const;

  // Stores of at most this many rows are searched by SearchEveryRow where the build has the
  // product's row kernel (gemv_row.h): in a store this small the staged bounds prune too little
  // to pay for their bookkeeping (KITTI 00 broadcast, 100 robots: about 45 rows a robot;
  // docs/performance.md).
  static constexpr std::size_t kReadEveryRow = 64;
  std::optional<IndexMatch> SearchEveryRow(const float* query, const FrameInterval& skip, float q_norm) const;

  // The screen's limits (one a check) for a best model distance so far.
  void SetLimits(float best, double margin) const;

  // What a search of a small store reads first, together (SearchEveryRow: two cache lines).
  int dim_;
  std::uint64_t changes_ = 0;
  // The previous search's winner: consecutive queries to one robot are usually neighbouring
  // frames, so its distance is a tight first bound. Only a hint: any value gives the same result.
  mutable std::size_t hint_ = 0;
  std::vector<float> data_;   // size() x dim, row-major
  std::vector<float> norms_;  // squared norms of the rows
  std::vector<IndexEntry> entries_;
  mutable std::vector<float> scratch_;
  float max_norm_ = 0.0f;     // max of norms_: scales the rounding margin of the bounds
  HalfScreen screen_;                  // every row again in half precision, for the bounds
  mutable std::vector<float> limits_;  // per check of the screen: the largest partial sum that can still win
};

}  // namespace dvpr
