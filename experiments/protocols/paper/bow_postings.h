#pragma once
// The static protocol's inverted index over every frame's BoW vector (docs/bow.md): per word the
// frames that contain it, and the search for the frame a query part scores best outside the
// query's suppression window. The sweep's cost at 2000 words a frame is almost all here (about
// 300 M postings per evaluation of the distributed index, most of them common words'), so the
// layout and the loop are written for memory traffic, not for brevity:
// - the postings are one array, word by word, with each word's start (two reads per query word
//   instead of a vector per word); a query's runs are looked up once (AppendRuns) and every part
//   of it is searched from them;
// - a search asks for the postings of the runs a few ahead (the next part's too), so the reads,
//   which miss the cache (the words are spread over a vocabulary of up to 10^7), overlap;
// - the window is not cut out of a run (a binary search per word, mispredicted): its frames are
//   summed like the others and left out when the best is picked. Each frame's sum is its own,
//   so the others' are unchanged.
//
// The score of frame j is the sum over the part's words, in the part's order, of
// min(query, stored) weight as a double: the order of SharedMinimum (agents/algorithms/bow_vector.h),
// so every score is that function's to the last bit (test BowPostingsTest).
#include <cstdint>
#include <span>
#include <vector>

#include "experiments/domain/data/bow_data.h"

namespace dvpr {

class BowPostings {
 public:
  struct Posting {
    std::int32_t frame;
    float weight;
  };
  // One query word: the frames that contain it (ascending), its weight in the query, and how
  // many of those frames lie outside the query's window.
  struct Run {
    const Posting* begin;
    const Posting* end;
    float weight;
    std::int32_t outside;
  };
  struct Best {
    std::int32_t frame = -1;  // -1: no frame outside the window shares a word
    double score = 0.0;
  };
  // A search's working memory, one per thread: a sum per frame (all 0 between searches) and the
  // frames touched.
  class Scratch {
   public:
    explicit Scratch(std::size_t frames) : sums_(frames, 0.0), touched_(frames) {}

   private:
    friend class BowPostings;
    std::vector<double> sums_;
    std::vector<std::int32_t> touched_;
  };

  // `bow` is copied into postings; it need not outlive this.
  explicit BowPostings(const BowData& bow);

  std::size_t frames() const { return frames_; }
  // Appends the runs of v's words, in v's order, for query `query` and its window (frames j with
  // |query - j| <= window). This is where a query's postings are read from memory (prefetched a
  // few words ahead, so the reads overlap); its searches, one per part and word assignment,
  // then find them in the cache.
  void AppendRuns(const BowVector& v, std::int32_t query, int window, std::vector<Run>& runs) const;
  // The frame of highest score for one part of query `query` (`runs`, from AppendRuns with the
  // same query and window), among the frames outside the window; ties to the lower frame. Adds to
  // `visited` the postings of those frames (the search's unit of work).
  Best Search(std::int32_t query, int window, std::span<const Run> runs, Scratch& scratch,
              std::int64_t& visited) const;

 private:
  std::size_t frames_ = 0;
  std::vector<Posting> postings_;     // word by word; within a word the frames containing it, ascending
  std::vector<std::int64_t> starts_;  // word w's postings: [starts_[w], starts_[w + 1])
};

}  // namespace dvpr
