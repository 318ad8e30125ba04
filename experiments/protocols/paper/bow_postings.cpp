#include "experiments/protocols/paper/bow_postings.h"

#include <algorithm>
#include <type_traits>

namespace dvpr {

namespace {

// Runs this many ahead are prefetched while one is summed: a run of a common word is about 55
// postings (7 cache lines), summed in about as long as a read from memory takes.
constexpr std::size_t kRunsAhead = 8;
// A search asks again for the postings of the run this many ahead of the one it sums.
constexpr std::size_t kSearchAhead = 4;
// Word starts are looked up this many words ahead.
constexpr std::size_t kStartsAhead = 32;

void PrefetchRun(const BowPostings::Posting* begin, const BowPostings::Posting* end) {
  constexpr int kMaxLines = 16;  // a longer run: the hardware prefetcher follows the rest
  const char* line = reinterpret_cast<const char*>(begin);
  const char* const last = reinterpret_cast<const char*>(end);
  for (int n = 0; n < kMaxLines && line < last; ++n, line += 64) __builtin_prefetch(line);
}

// The largest of sums[begin, end) (0 when empty): four maxima at once, as one running maximum
// would wait for each comparison before the next.
double Largest(const double* sums, std::int32_t begin, std::int32_t end) {
  double m0 = 0.0, m1 = 0.0, m2 = 0.0, m3 = 0.0;
  std::int32_t j = begin;
  for (; j + 4 <= end; j += 4) {
    m0 = std::max(m0, sums[j]);
    m1 = std::max(m1, sums[j + 1]);
    m2 = std::max(m2, sums[j + 2]);
    m3 = std::max(m3, sums[j + 3]);
  }
  for (; j < end; ++j) m0 = std::max(m0, sums[j]);
  return std::max(std::max(m0, m1), std::max(m2, m3));
}

}  // namespace

BowPostings::BowPostings(const BowData& bow) : frames_(bow.frames.size()) {
  starts_.assign(static_cast<std::size_t>(bow.vocabulary) + 1, 0);
  for (const BowVector& frame : bow.frames) {
    for (const BowEntry& e : frame) ++starts_[static_cast<std::size_t>(e.word) + 1];
  }
  for (std::size_t w = 1; w < starts_.size(); ++w) starts_[w] += starts_[w - 1];
  postings_.resize(static_cast<std::size_t>(starts_.back()));
  std::vector<std::int64_t> next(starts_.begin(), starts_.end() - 1);
  for (std::size_t f = 0; f < bow.frames.size(); ++f) {
    for (const BowEntry& e : bow.frames[f]) {
      postings_[static_cast<std::size_t>(next[static_cast<std::size_t>(e.word)]++)] = {static_cast<std::int32_t>(f),
                                                                                      e.weight};
    }
  }
}

void BowPostings::AppendRuns(const BowVector& v, std::int32_t query, int window, std::vector<Run>& runs) const {
  const Posting* const postings = postings_.data();
  const std::int64_t* const starts = starts_.data();
  const auto word = [&](std::size_t k) { return static_cast<std::size_t>(v[k].word); };
  const auto before = [](const Posting& p, std::int32_t frame) { return p.frame < frame; };
  for (std::size_t k = 0; k < v.size(); ++k) {
    if (k + kStartsAhead < v.size()) __builtin_prefetch(&starts[word(k + kStartsAhead)]);
    if (k + kRunsAhead < v.size()) {
      const std::size_t w = word(k + kRunsAhead);
      PrefetchRun(postings + starts[w], postings + starts[w + 1]);
    }
    const std::size_t w = word(k);
    const Posting* const begin = postings + starts[w];
    const Posting* const end = postings + starts[w + 1];
    // The window's postings are one stretch of the run (frames ascending).
    const Posting* const lo = std::lower_bound(begin, end, query - window, before);
    const Posting* const hi = std::lower_bound(lo, end, query + window + 1, before);
    runs.push_back({begin, end, v[k].weight, static_cast<std::int32_t>((lo - begin) + (end - hi))});
  }
}

BowPostings::Best BowPostings::Search(std::int32_t query, int window, std::span<const Run> runs, Scratch& scratch,
                                      std::int64_t& visited) const {
  double* const sums = scratch.sums_.data();
  std::int64_t all = 0;
  for (const Run& run : runs) {
    all += run.end - run.begin;
    visited += run.outside;
  }
  // Few postings (a small part, rare words): remember the frames touched and look only at those.
  // Many: sum without bookkeeping (a branch per posting, mispredicted at each first touch, would
  // cost more) and look at every frame.
  const bool dense = all * 4 >= static_cast<std::int64_t>(frames_);
  std::int32_t* const touched = scratch.touched_.data();
  std::int32_t* last = touched;
  const auto sum = [&](auto track) {
    const std::size_t count = runs.size();
    for (std::size_t k = 0; k < count; ++k) {
      // The query's postings were read once (AppendRuns), but the searches of a batch's other
      // assignments push them out of the first-level caches: ask for a run a few ahead again.
      if (k + kSearchAhead < count) PrefetchRun(runs[k + kSearchAhead].begin, runs[k + kSearchAhead].end);
      const Run& run = runs[k];
      const float q = run.weight;
      const Posting* const end = run.end;  // a local: through `run`, every store to sums reloaded it
      for (const Posting* p = run.begin; p != end; ++p) {
        const std::int32_t j = p->frame;
        if constexpr (decltype(track)::value) {
          if (sums[j] == 0.0) *last++ = j;  // every weight is > 0: a touched sum is never 0
        }
        // min of two floats is one of them, so converting after the min gives the same double.
        sums[j] += static_cast<double>(std::min(q, p->weight));
      }
    }
  };
  // The best frame outside the window (ties: the lower frame); a frame that shares no word has
  // sum 0 and never wins. Every sum goes back to 0 for the next search.
  const auto n = static_cast<std::int32_t>(frames_);
  const std::int32_t below = std::clamp(query - window, 0, n), above = std::clamp(query + window + 1, 0, n);
  Best best;
  if (dense) {
    sum(std::false_type{});
    const double top = std::max(Largest(sums, 0, below), Largest(sums, above, n));
    if (top > 0.0) {
      std::int32_t j = 0;
      while (j < below && sums[j] != top) ++j;
      if (j == below) {
        j = above;
        while (sums[j] != top) ++j;
      }
      best = {j, top};
    }
    std::fill(sums, sums + n, 0.0);
    return best;
  }
  sum(std::true_type{});
  for (const std::int32_t* t = touched; t != last; ++t) {
    const std::int32_t j = *t;
    if ((j < below || j >= above) && (sums[j] > best.score || (sums[j] == best.score && j < best.frame))) {
      best = {j, sums[j]};
    }
    sums[j] = 0.0;
  }
  return best;
}

}  // namespace dvpr
