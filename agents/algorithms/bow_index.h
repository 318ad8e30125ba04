#pragma once
// What one robot of a bag-of-words team keeps and searches (docs/bow.md, step 3 of the
// distributed inverted index): the parts of frames' BoW vectors it was sent, as an inverted
// index (word -> the stored frames containing it, with their weights).
//
// A search scores a part of a query against every stored frame sharing one of its words: the sum
// over the shared words of min(query, stored) weight, which for L1-normalised vectors is the
// share of DBoW2's L1 score these words contribute (agents/algorithms/bow_vector.h, SharedMinimum). The
// best is the highest score, ties to the lower frame id, never a frame in the suppression window of the
// query: the same rule and the same summation order (the query's words ascending) as the static
// protocol's (experiments/protocols/paper/static_bow.h), so both compute identical scores.
#include <cstdint>
#include <optional>
#include <unordered_map>
#include <vector>

#include "agents/algorithms/bow_vector.h"
#include "agents/algorithms/ids.h"
#include "agents/algorithms/index.h"

namespace dvpr {

struct BowIndexMatch {
  RobotId robot;  // the robot that observed the frame
  FrameId frame;
  double score = 0.0;
};

// comparisons: postings visited outside the window (what the search cost).
using BowSearchResult = SearchResult<BowIndexMatch>;

class BowIndex final : public Index<const BowVector&, BowIndexMatch> {
 public:
  // Sparse: a part's entries name their words.
  int dim() const override { return 0; }
  // Parts stored (one a frame).
  std::size_t size() const override { return observer_.size(); }
  // Keeps `part` of `frame`, observed by `robot`. A frame already stored is kept once (a
  // duplicated message on a real network adds nothing).
  void Add(RobotId robot, FrameId frame, const BowVector& part) override;
  BowSearchResult Search(const BowVector& part, FrameId query, const FrameWindow& window) const override;

  std::int64_t postings() const { return postings_count_; }

 private:
  struct Posting {
    std::int32_t frame;
    float weight;
  };
  std::unordered_map<std::int32_t, std::vector<Posting>> postings_;  // by word
  std::unordered_map<std::int32_t, RobotId> observer_;               // by stored frame
  std::int64_t postings_count_ = 0;
  // A search's running sums, by frame id (sized to the largest stored frame), and the frames it
  // touched: reset after each search, so a search costs the postings it visits.
  mutable std::vector<double> sums_;
  mutable std::vector<std::int32_t> touched_;
};

}  // namespace dvpr
