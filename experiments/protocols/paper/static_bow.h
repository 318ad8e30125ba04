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
#include <functional>
#include <future>
#include <map>
#include <memory>
#include <mutex>
#include <span>
#include <string>
#include <tuple>
#include <vector>

#include "agents/algorithms/bow_words.h"
#include "agents/placement/placement.h"
#include "experiments/domain/data/bow_data.h"
#include "experiments/protocols/paper/bow_postings.h"
#include "experiments/protocols/paper/static_protocol.h"
#include "experiments/results/bow_rows.h"

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
BowRunResult DescriptorQueryTraffic(const PlacementStrategy* routing, int robots, const DescriptorMatrix& x);

class BowEvaluator {
 public:
  // One word assignment of the distributed index, strategy `name`.
  struct Assignment {
    const WordOwners* owners = nullptr;
    std::string name;
  };
  // One EvaluatePlanned will be asked for: `words` builds its owners (called once, when its
  // batch is evaluated, so the owners of every planned assignment are not all held at once).
  struct PlannedAssignment {
    std::string name;
    int robots = 0;
    std::function<std::shared_ptr<const WordOwners>()> words;
  };
  // Assignments evaluated together by EvaluatePlanned: each query's postings are read from memory
  // once for all of them, while the batch's owners are held (2 MB each at a vocabulary of 10^6;
  // fewer assignments a batch when the vocabulary is larger, so they stay within 32 MB).
  static constexpr std::size_t kBatch = 16;

  // `paper` gives the deployment, ground truth and R; `bow` one vector per frame (kept by reference).
  BowEvaluator(const PaperEvaluator& paper, const BowData& bow);

  const PrResult& centralized() const { return centralized_; }

  // The distributed inverted index over `owners`, strategy `name`.
  BowRunResult Evaluate(const WordOwners& owners, const std::string& name, bool keep_curve) const;
  // Evaluate for each assignment, in one pass over the queries; the results in their order.
  std::vector<BowRunResult> EvaluateMany(std::span<const Assignment> assignments, bool keep_curve) const;
  // The assignments the sweep's runs will ask for (its bow_decentralized* strategies at every n,
  // in the order its runs come), each built only when its batch is evaluated. Call before the
  // first EvaluatePlanned.
  void Plan(std::vector<PlannedAssignment> planned);
  bool IsPlanned(const std::string& name, int robots) const;
  // A planned assignment's evaluation without its curve, computed once and then copied: the word
  // assignments do not depend on the run (BowPlacement takes none), so the runs of one n ask for
  // the same one. The first request evaluates it with the next planned ones not yet started,
  // kBatch in all (EvaluateMany). Safe to call from several threads; a call that finds its
  // evaluation under way in another thread evaluates the next planned ones not started instead
  // of waiting (so the sweep's threads share the evaluations), and waits only when none are left.
  // Throws std::logic_error when (name, robots) is not planned.
  BowRunResult EvaluatePlanned(const std::string& name, int robots) const;
  // Evaluate without its curve, computed once per (name, owners) and then copied, for owners not
  // planned. Safe to call from several threads, as EvaluatePlanned.
  BowRunResult EvaluateShared(const WordOwners& owners, const std::string& name) const;
  // The centralized reference (every query to one index) and broadcast (the full vector to the
  // n - 1 others, each answers from its own frames, the best answer wins: the centralized ranking).
  BowRunResult Reference(const std::string& name, int robots, bool broadcast) const;

 private:
  struct Planned {
    PlannedAssignment assignment;
    bool started = false;
    std::shared_future<BowRunResult> result;
  };
  // Evaluates the planned assignments `batch` (indices into planned_) and fulfils `promises`.
  void EvaluateBatch(const std::vector<std::size_t>& batch, std::vector<std::promise<BowRunResult>>& promises) const;

  const PaperEvaluator& paper_;
  const BowData& bow_;
  BowPostings postings_;
  mutable std::mutex shared_mutex_;
  mutable std::vector<Planned> planned_;
  // Evaluations not planned, by (name, robots, a 64-bit digest of every word's owner): a digest
  // rather than a copy of the owners.
  mutable std::map<std::tuple<std::string, int, std::uint64_t>, std::shared_future<BowRunResult>> shared_;
  std::vector<std::int32_t> central_best_;      // per query: the centralized best frame (-1: none)
  PrResult centralized_;
};

}  // namespace dvpr
