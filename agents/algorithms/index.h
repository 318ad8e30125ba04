#pragma once
// What a robot keeps and searches, whatever it matches with (FAISS's Index: dim, size, Add,
// Search). The descriptor store (IncrementalIndex, agents/algorithms/descriptor_index.h: dense float rows,
// nearest squared L2) and the bag-of-words inverted index (BowIndex, agents/algorithms/bow_index.h: sparse
// parts, highest shared-minimum score) are its two implementations.
//
// The interface is per query, not per row: a search is one call whose loops over the stored rows
// are the implementation's own. Both implementations are final, so an agent that holds its own
// store by its class calls them without a virtual call.
#include <cstddef>
#include <cstdint>
#include <optional>

#include "agents/algorithms/frame_window.h"
#include "agents/algorithms/ids.h"

namespace dvpr {

// Who observed a stored frame and which frame it is.
struct IndexEntry {
  RobotId robot;  // robot that observed the frame
  FrameId frame;  // frame index in the full sequence
};

// A search's answer: the best stored frame outside the suppression window, if any, and what
// finding it cost (the service-time model's comparisons).
template <class Match>
struct SearchResult {
  std::optional<Match> best;
  std::int64_t comparisons = 0;
};

// `Vector` is how a query or a stored vector is passed (a pointer to dim() floats; a sparse
// part); `Match` what a search finds.
template <class Vector, class Match>
class Index {
 public:
  using Result = SearchResult<Match>;

  virtual ~Index() = default;

  // Length of a dense vector; 0 for a sparse one (its entries name their own dimension).
  virtual int dim() const = 0;
  // Vectors stored.
  virtual std::size_t size() const = 0;
  // Keeps `vector` of `frame`, observed by `robot`.
  virtual void Add(RobotId robot, FrameId frame, Vector vector) = 0;
  // The best stored entry whose frame is outside query_frame's suppression window.
  virtual Result Search(Vector query, FrameId query_frame, const FrameWindow& window) const = 0;
};

}  // namespace dvpr
