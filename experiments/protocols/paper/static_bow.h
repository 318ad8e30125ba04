#pragma once
// Bag-of-words place recognition in the static protocol (docs/bow.md): the centralized BoW
// reference, BoW broadcast and the distributed inverted index (Cieslewski and Scaramuzza, ICRA
// 2017) over the dataset's BoW vectors, with the paper protocol's ground truth and AUC.
//
// As in the paper protocol, every frame is a query and every other frame outside its window is
// stored (non-causal). Centralized: the frame of highest L1 score. Distributed: the words are
// assigned to robots (WordOwners); robot r scores the query's part on its words against the
// parts of every frame it stored, returns its best frame (highest partial score, ties the lower
// frame id); the querying robot takes the vote of agents/algorithms/bow_words.h. A query's score for the
// ranking is 1 - the L1 score (centralized) or 1 - the voters' summed partial scores.
//
// Bytes: every part goes to its owner as one bow_query_t (the querying robot keeps its own part,
// and a robot that owns none of the query's words gets nothing); its encoded size is counted
// (payload_bytes, LCM encoding with the fingerprint; no wire overheads: the static protocol has
// no network). Broadcast sends the full vector to the n - 1 others.
#include <cstdint>
#include <future>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <tuple>
#include <vector>

#include "agents/algorithms/bow_words.h"
#include "agents/routing/routing.h"
#include "experiments/data/bow_data.h"
#include "experiments/results/bow_rows.h"
#include "experiments/protocols/paper/static_protocol.h"

namespace dvpr {

struct BowRunResult {
  PaperRunResult paper;               // row (messages, payload_bytes set), per_robot, curve
  BowRow bow;                         // bow.csv
  std::map<std::int64_t, std::int64_t> part_sizes;  // encoded partial-query bytes -> messages
  std::vector<MatchOutcome> matches;  // Evaluate: per query, the voted frame and 1 - its score
};

// The query traffic of a descriptor strategy in the same terms, for the BoW comparison: every
// frame's query_t (encoded) to each robot other than its taker that searches or stores it;
// `routing` null means broadcast (the n - 1 others). Fills bow (queries, partial_queries =
// those messages, payload_bytes, the size quantiles) and part_sizes; no vote.
BowRunResult DescriptorQueryTraffic(const RoutingStrategy* routing, int robots, const DescriptorMatrix& x);

class BowEvaluator {
 public:
  // `paper` gives the deployment, ground truth and R; `bow` one vector per frame (kept by reference).
  BowEvaluator(const PaperEvaluator& paper, const BowData& bow);

  const PrResult& centralized() const { return centralized_; }

  // The distributed inverted index over `owners`, strategy `name`.
  BowRunResult Evaluate(const WordOwners& owners, const std::string& name, bool keep_curve) const;
  // Evaluate without its curve, computed once per (name, owners) and then copied: the word
  // assignments do not depend on the run, so the runs of one n ask for the same evaluation (at
  // about 2000 words a frame, most of a sweep's time). Safe to call from several threads; a
  // call that finds the same evaluation under way waits for it.
  BowRunResult EvaluateShared(const WordOwners& owners, const std::string& name) const;
  // The centralized reference (every query to one index) and broadcast (the full vector to the
  // n - 1 others, each answers from its own frames, the best answer wins: the centralized ranking).
  BowRunResult Reference(const std::string& name, int robots, bool broadcast) const;

 private:
  struct Posting {
    std::int32_t frame;
    float weight;
  };
  struct Best {
    std::int32_t frame = -1;
    double score = 0.0;
  };
  // The best frame for `part` of query `i` (outside its window), counting postings visited.
  Best Search(std::int32_t i, const BowVector& part, std::vector<double>& acc, std::vector<std::int32_t>& touched,
              std::int64_t& visited) const;

  const PaperEvaluator& paper_;
  const BowData& bow_;
  mutable std::mutex shared_mutex_;
  // By (name, robots, a 64-bit digest of every word's owner): a digest rather than a copy of the
  // owners (2 MB each at a vocabulary of 10^6).
  mutable std::map<std::tuple<std::string, int, std::uint64_t>, std::shared_future<BowRunResult>> shared_;
  std::vector<Posting> postings_;     // word by word; within a word the frames containing it, ascending
  std::vector<std::int64_t> starts_;  // word w's postings: [starts_[w], starts_[w + 1])
  std::vector<std::int32_t> central_best_;      // per query: the centralized best frame (-1: none)
  PrResult centralized_;
};

}  // namespace dvpr
