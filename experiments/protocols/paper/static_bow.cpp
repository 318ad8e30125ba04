#include "experiments/protocols/paper/static_bow.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <exception>
#include <optional>
#include <stdexcept>

#include "agents/messages/bow_query.h"
#include "agents/messages/team_sync.h"  // Fnv1a
#include "experiments/domain/data/split.h"
#include "experiments/results/protocol_traits.h"

namespace dvpr {

namespace {

// Median, 90th percentile (nearest rank) and largest of the sizes in a size -> count histogram.
void FillQuantiles(const std::map<std::int64_t, std::int64_t>& sizes, BowRow& row) {
  std::int64_t total = 0;
  for (const auto& [bytes, count] : sizes) total += count;
  if (total == 0) return;
  const auto rank = [total](double q) { return static_cast<std::int64_t>(q * static_cast<double>(total - 1)); };
  const std::int64_t r50 = rank(0.5), r90 = rank(0.9);
  std::int64_t seen = 0;
  for (const auto& [bytes, count] : sizes) {
    if (seen <= r50 && r50 < seen + count) row.part_bytes_p50 = bytes;
    if (seen <= r90 && r90 < seen + count) row.part_bytes_p90 = bytes;
    seen += count;
  }
  row.part_bytes_max = sizes.rbegin()->first;
}

// The encoded size of a bow_query_t of `words` words: it depends on the count only (fixed-size
// fields and two arrays of 4-byte values), so one is encoded per count and remembered in `memo`.
std::int64_t QueryBytes(std::size_t words, std::vector<std::int64_t>& memo) {
  if (memo.size() <= words) memo.resize(words + 1, 0);
  if (memo[words] == 0) memo[words] = EncodedBowQueryBytes(BowVector(words));
  return memo[words];
}

MatchOutcome Outcome(std::int32_t i, std::int32_t frame, double score) {
  MatchOutcome o;
  o.query = FrameId(i);
  if (frame >= 0) {
    o.match = FrameId(frame);
    o.score = 1.0 - score;  // ranked ascending, as distances
  }
  return o;
}

// One word assignment's evaluation, a query at a time (BowEvaluator::EvaluateMany): each query's
// runs grouped by owner (a stable counting sort, so each part keeps the word order
// WordOwners::Split gives it), each part searched, the answers voted, the counts kept.
class DistributedTally {
 public:
  DistributedTally(const WordOwners& owners, std::size_t frames)
      : robots_(static_cast<std::size_t>(owners.robots())),
        split_(SplitSequence(static_cast<int>(frames), owners.robots())),
        searches_(robots_, 0),
        comparisons_(robots_, 0),
        stored_(robots_, 0),
        part_(robots_ + 1),
        next_(robots_) {}

  // Query i (vector v, its runs in v's order, the owner of each of its words).
  void Query(const BowPostings& postings, int window, std::int32_t i, const BowVector& v,
             std::span<const BowPostings::Run> runs, std::span<const std::int16_t> owner, std::int32_t central_best,
             BowPostings::Scratch& scratch) {
    GroupByOwner(runs, owner);
    const auto ui = static_cast<std::size_t>(i);
    answers_.clear();
    for (std::size_t r = 0; r < robots_; ++r) {
      const std::size_t size = part_[r + 1] - part_[r];
      if (size == 0) continue;
      ++searches_[r];
      ++stored_[r];
      if (split_.owner[ui].value != static_cast<int>(r)) {
        ++out_.part_sizes[QueryBytes(size, part_bytes_)];
        part_words_ += static_cast<std::int64_t>(size);
      }
      const BowPostings::Best best = postings.Search(
          i, window, std::span(grouped_).subspan(part_[r], size), scratch, comparisons_[r]);
      if (best.frame >= 0) {
        answers_.push_back({RobotId(static_cast<int>(r)), split_.owner[static_cast<std::size_t>(best.frame)],
                            FrameId(best.frame), best.score});
      }
    }
    words_ += static_cast<std::int64_t>(v.size());
    const std::optional<VotedMatch> voted = Vote(answers_);
    matches_.push_back(Outcome(i, voted ? voted->frame.value : -1, voted ? voted->score : 0.0));
    if (voted) {
      ++out_.bow.voted;
      if (voted->frame.value != central_best) ++out_.bow.vote_not_centralized;
    }
  }

  BowRunResult Finish(const PaperEvaluator& paper, const std::string& name, bool keep_curve,
                      const PrResult& centralized) {
    PrResult pr = EvaluatePr(matches_, paper.deployment().trajectory.positions, paper.evaluation().radius_m,
                             paper.relevant());
    const auto queries = static_cast<std::int64_t>(matches_.size());
    out_.matches = std::move(matches_);
    paper.FillResult(name, std::move(pr), searches_, comparisons_, stored_, keep_curve, out_.paper);
    out_.paper.row.auc_reference = centralized.auc;
    out_.paper.row.relative_auc = RelativeAuc(out_.paper.row.auc, centralized.auc);
    for (const auto& [bytes, count] : out_.part_sizes) {
      out_.bow.partial_queries += count;
      out_.bow.payload_bytes += bytes * count;
    }
    out_.bow.queries = queries;
    out_.bow.mean_words = static_cast<double>(words_) / static_cast<double>(queries);
    if (out_.bow.partial_queries > 0) {
      out_.bow.mean_part_words = static_cast<double>(part_words_) / static_cast<double>(out_.bow.partial_queries);
    }
    FillQuantiles(out_.part_sizes, out_.bow);
    out_.paper.row.messages = out_.bow.partial_queries;
    out_.paper.row.payload_bytes = out_.bow.payload_bytes;
    return std::move(out_);
  }

 private:
  // Part r of the query: grouped_[part_[r], part_[r + 1]).
  void GroupByOwner(std::span<const BowPostings::Run> runs, std::span<const std::int16_t> owner) {
    std::fill(part_.begin(), part_.end(), 0);
    for (const std::int16_t r : owner) ++part_[static_cast<std::size_t>(r) + 1];
    for (std::size_t r = 0; r < robots_; ++r) part_[r + 1] += part_[r];
    std::copy(part_.begin(), part_.end() - 1, next_.begin());
    grouped_.resize(runs.size());
    for (std::size_t k = 0; k < runs.size(); ++k) grouped_[next_[static_cast<std::size_t>(owner[k])]++] = runs[k];
  }

  std::size_t robots_;
  SequenceSplit split_;
  BowRunResult out_;
  std::vector<std::int64_t> searches_, comparisons_, stored_;
  std::vector<MatchOutcome> matches_;
  std::vector<PartialMatch> answers_;
  std::int64_t words_ = 0, part_words_ = 0;
  std::vector<std::size_t> part_, next_;
  std::vector<BowPostings::Run> grouped_;
  std::vector<std::int64_t> part_bytes_;
};

// A 64-bit digest of the vocabulary and every word's owner (the key of a shared evaluation).
std::uint64_t OwnersDigest(const WordOwners& owners) {
  Fnv1a hash;
  hash.AddValue(owners.vocabulary());
  for (std::int32_t w = 0; w < owners.vocabulary(); ++w) hash.AddValue(owners.OwnerOf(w).value);
  return static_cast<std::uint64_t>(hash.value());
}

}  // namespace

BowRunResult DescriptorQueryTraffic(const PlacementStrategy* routing, int robots, const DescriptorMatrix& x) {
  const SequenceSplit split = SplitSequence(static_cast<int>(x.rows()), robots);
  const std::int64_t bytes = EncodedDescriptorQueryBytes(static_cast<int>(x.cols()));
  BowRunResult out;
  std::int64_t messages = 0;
  for (Eigen::Index i = 0; i < x.rows(); ++i) {
    const RobotId taker = split.owner[static_cast<std::size_t>(i)];
    if (routing == nullptr) {
      messages += robots - 1;
      continue;
    }
    const PlacementDecision d = routing->Route(taker, x.row(i).data());
    std::vector<RobotId> to(d.search_at);
    to.insert(to.end(), d.store_at.begin(), d.store_at.end());
    std::sort(to.begin(), to.end());
    to.erase(std::unique(to.begin(), to.end()), to.end());
    messages += static_cast<std::int64_t>(std::count_if(to.begin(), to.end(), [&](RobotId r) { return r != taker; }));
  }
  if (messages > 0) out.part_sizes[bytes] = messages;
  out.bow.queries = static_cast<std::int64_t>(x.rows());
  out.bow.partial_queries = messages;
  out.bow.payload_bytes = messages * bytes;
  FillQuantiles(out.part_sizes, out.bow);
  return out;
}

BowEvaluator::BowEvaluator(const PaperEvaluator& paper, const BowData& bow)
    : paper_(paper), bow_(bow), postings_(bow) {
  if (static_cast<Eigen::Index>(bow.frames.size()) != paper.deployment().size()) {
    throw std::invalid_argument("BowEvaluator: " + std::to_string(bow.frames.size()) + " BoW vectors for " +
                                std::to_string(paper.deployment().size()) + " frames");
  }
  const int window = paper.evaluation().suppression_frames;
  BowPostings::Scratch scratch(bow.frames.size());
  std::vector<BowPostings::Run> runs;
  std::vector<MatchOutcome> matches;
  std::int64_t visited = 0;
  for (std::size_t i = 0; i < bow.frames.size(); ++i) {
    runs.clear();
    const auto fi = static_cast<std::int32_t>(i);
    postings_.AppendRuns(bow.frames[i], fi, window, runs);
    const BowPostings::Best best = postings_.Search(fi, window, runs, scratch, visited);
    central_best_.push_back(best.frame);
    matches.push_back(Outcome(fi, best.frame, best.score));
  }
  centralized_ = EvaluatePr(matches, paper.deployment().trajectory.positions, paper.evaluation().radius_m,
                            paper.relevant());
}

BowRunResult BowEvaluator::Evaluate(const WordOwners& owners, const std::string& name, bool keep_curve) const {
  const Assignment one{&owners, name};
  return std::move(EvaluateMany(std::span(&one, 1), keep_curve).front());
}

// A query's owners are looked up this many words ahead (reads from memory, as the words are
// spread over the vocabulary).
constexpr std::size_t kOwnersAhead = 32;

std::vector<BowRunResult> BowEvaluator::EvaluateMany(std::span<const Assignment> assignments, bool keep_curve) const {
  const std::vector<BowVector>& frames = bow_.frames;
  const int window = paper_.evaluation().suppression_frames;
  const std::size_t batch = assignments.size();
  std::vector<DistributedTally> tallies;
  tallies.reserve(batch);
  for (const Assignment& a : assignments) tallies.emplace_back(*a.owners, frames.size());
  // Every assignment's owner of word w side by side at [w x batch, (w + 1) x batch): a query's
  // owners are then one cache line per word, not one per word and assignment (which, at 2 MB an
  // assignment, pushed the query's postings out of the cache between its searches).
  std::vector<std::int16_t> owners(static_cast<std::size_t>(bow_.vocabulary) * batch);
  for (std::size_t a = 0; a < batch; ++a) {
    for (std::int32_t w = 0; w < bow_.vocabulary; ++w) {
      owners[static_cast<std::size_t>(w) * batch + a] = static_cast<std::int16_t>(assignments[a].owners->OwnerOf(w).value);
    }
  }
  BowPostings::Scratch scratch(frames.size());
  std::vector<BowPostings::Run> runs;
  std::vector<std::int16_t> query_owners;  // assignment a's owner of the query's word k at [a x words + k]
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const auto fi = static_cast<std::int32_t>(i);
    const BowVector& v = frames[i];
    runs.clear();
    postings_.AppendRuns(v, fi, window, runs);  // the query's postings into the cache, for all
    query_owners.resize(v.size() * batch);
    for (std::size_t k = 0; k < v.size(); ++k) {
      if (k + kOwnersAhead < v.size()) __builtin_prefetch(owners.data() + static_cast<std::size_t>(v[k + kOwnersAhead].word) * batch);
      const std::int16_t* row = owners.data() + static_cast<std::size_t>(v[k].word) * batch;
      for (std::size_t a = 0; a < batch; ++a) query_owners[a * v.size() + k] = row[a];
    }
    for (std::size_t a = 0; a < batch; ++a) {
      tallies[a].Query(postings_, window, fi, v, runs, std::span(query_owners).subspan(a * v.size(), v.size()),
                       central_best_[i], scratch);
    }
  }
  std::vector<BowRunResult> out;
  for (std::size_t a = 0; a < batch; ++a) out.push_back(tallies[a].Finish(paper_, assignments[a].name, keep_curve, centralized_));
  return out;
}

void BowEvaluator::Plan(std::vector<PlannedAssignment> planned) {
  const std::lock_guard lock(shared_mutex_);
  planned_.clear();
  for (PlannedAssignment& p : planned) planned_.push_back({std::move(p), false, {}});
}

bool BowEvaluator::IsPlanned(const std::string& name, int robots) const {
  const std::lock_guard lock(shared_mutex_);
  return std::any_of(planned_.begin(), planned_.end(), [&](const Planned& p) {
    return p.assignment.name == name && p.assignment.robots == robots;
  });
}

void BowEvaluator::EvaluateBatch(const std::vector<std::size_t>& batch,
                                 std::vector<std::promise<BowRunResult>>& promises) const {
  std::vector<BowRunResult> results;
  try {
    std::vector<std::shared_ptr<const WordOwners>> owners;
    std::vector<Assignment> assignments;
    for (const std::size_t p : batch) owners.push_back(planned_[p].assignment.words());
    for (std::size_t k = 0; k < batch.size(); ++k) assignments.push_back({owners[k].get(), planned_[batch[k]].assignment.name});
    results = EvaluateMany(assignments, false);
  } catch (...) {
    for (auto& promise : promises) promise.set_exception(std::current_exception());
    return;
  }
  for (std::size_t k = 0; k < batch.size(); ++k) promises[k].set_value(std::move(results[k]));
}

BowRunResult BowEvaluator::EvaluatePlanned(const std::string& name, int robots) const {
  for (;;) {
    std::shared_future<BowRunResult> result;
    std::vector<std::size_t> batch;
    std::vector<std::promise<BowRunResult>> promises;
    {
      const std::lock_guard lock(shared_mutex_);
      const auto it = std::find_if(planned_.begin(), planned_.end(), [&](const Planned& p) {
        return p.assignment.name == name && p.assignment.robots == robots;
      });
      if (it == planned_.end()) {
        throw std::logic_error("BowEvaluator::EvaluatePlanned: " + name + " at n = " + std::to_string(robots) +
                               " was not planned");
      }
      result = it->result;
      // Not started: this one and the next planned ones not started yet. Under way in another
      // thread: rather than wait, the next ones not started (the sweep's threads share the
      // evaluations instead of one computing while the others wait). Each result is its own
      // whichever batch computed it (BowPostingsTest), so the outputs do not depend on this.
      const bool mine = !it->started;
      const bool ready = it->started && result.wait_for(std::chrono::seconds(0)) == std::future_status::ready;
      auto from = mine ? it : std::find_if(planned_.begin(), planned_.end(), [](const Planned& p) { return !p.started; });
      if (!ready && from != planned_.end()) {
        // The batch's owners side by side take 2 bytes per word and assignment: at most 32 MB.
        const auto per_assignment = 2 * static_cast<std::size_t>(std::max(bow_.vocabulary, 1));
        const std::size_t most = std::clamp<std::size_t>((std::size_t{32} << 20) / per_assignment, 1, kBatch);
        for (auto p = from; p != planned_.end() && batch.size() < most; ++p) {
          if (p->started) continue;
          p->started = true;
          promises.emplace_back();
          p->result = promises.back().get_future().share();
          batch.push_back(static_cast<std::size_t>(p - planned_.begin()));
        }
        if (mine) result = it->result;
      }
    }
    if (batch.empty()) return result.get();  // a copy: the caller sets its run's key
    EvaluateBatch(batch, promises);
  }
}

BowRunResult BowEvaluator::EvaluateShared(const WordOwners& owners, const std::string& name) const {
  const std::uint64_t digest = OwnersDigest(owners);
  std::promise<BowRunResult> promise;
  std::shared_future<BowRunResult> result;
  bool mine = false;
  {
    const std::lock_guard lock(shared_mutex_);
    auto [it, fresh] = shared_.try_emplace({name, owners.robots(), digest});
    if (fresh) it->second = promise.get_future().share();
    result = it->second;
    mine = fresh;
  }
  if (mine) {
    try {
      promise.set_value(Evaluate(owners, name, false));
    } catch (...) {
      promise.set_exception(std::current_exception());
    }
  }
  return result.get();  // a copy: the caller sets its run's key
}

BowRunResult BowEvaluator::Reference(const std::string& name, int robots, bool broadcast) const {
  const std::vector<BowVector>& frames = bow_.frames;
  BowRunResult out;
  RunResult& row = out.paper.row;
  row.key.protocol = kPaperProtocol;
  row.key.strategy = name;
  row.key.robots = robots;
  row.auc = centralized_.auc;
  row.auc_reference = centralized_.auc;
  row.relative_auc = RelativeAuc(row.auc, row.auc_reference);
  row.queries = static_cast<std::int64_t>(frames.size());
  std::vector<std::int64_t> bytes_by_words;
  std::int64_t words = 0;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    words += static_cast<std::int64_t>(frames[i].size());
    if (central_best_[i] >= 0) ++out.bow.voted;
    if (broadcast) out.part_sizes[QueryBytes(frames[i].size(), bytes_by_words)] += robots - 1;
  }
  out.bow.queries = row.queries;
  out.bow.mean_words = static_cast<double>(words) / static_cast<double>(frames.size());
  std::int64_t entries = 0;
  for (const auto& [bytes, count] : out.part_sizes) {
    out.bow.partial_queries += count;
    out.bow.payload_bytes += bytes * count;
    entries += (bytes - EncodedBowQueryBytes({})) / 8 * count;
  }
  if (out.bow.partial_queries > 0) {
    out.bow.mean_part_words = static_cast<double>(entries) / static_cast<double>(out.bow.partial_queries);
  }
  FillQuantiles(out.part_sizes, out.bow);
  row.messages = out.bow.partial_queries;
  row.payload_bytes = out.bow.payload_bytes;
  return out;
}

}  // namespace dvpr
