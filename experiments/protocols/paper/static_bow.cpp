#include "experiments/protocols/paper/static_bow.h"

#include <algorithm>
#include <cstdlib>
#include <exception>
#include <stdexcept>

#include "agents/messages/bow_query.h"
#include "experiments/data/split.h"
#include "experiments/results/protocol_traits.h"
#include "agents/messages/team_sync.h"  // Fnv1a

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

MatchOutcome Outcome(std::int32_t i, std::int32_t frame, double score) {
  MatchOutcome o;
  o.query = FrameId(i);
  if (frame >= 0) {
    o.match = FrameId(frame);
    o.score = 1.0 - score;  // ranked ascending, as distances
  }
  return o;
}

}  // namespace

BowRunResult DescriptorQueryTraffic(const RoutingStrategy* routing, int robots, const DescriptorMatrix& x) {
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
    const RoutingDecision d = routing->Route(taker, x.row(i).data());
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

BowEvaluator::BowEvaluator(const PaperEvaluator& paper, const BowData& bow) : paper_(paper), bow_(bow) {
  if (static_cast<Eigen::Index>(bow.frames.size()) != paper.deployment().size()) {
    throw std::invalid_argument("BowEvaluator: " + std::to_string(bow.frames.size()) + " BoW vectors for " +
                                std::to_string(paper.deployment().size()) + " frames");
  }
  // One array of postings, word by word (frames ascending within a word), and where each word's
  // run starts: two memory reads per query word instead of a vector per word.
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
  std::vector<double> acc(bow.frames.size(), 0.0);
  std::vector<std::int32_t> touched;
  std::vector<MatchOutcome> matches;
  std::int64_t visited = 0;
  for (std::size_t i = 0; i < bow.frames.size(); ++i) {
    const Best best = Search(static_cast<std::int32_t>(i), bow.frames[i], acc, touched, visited);
    central_best_.push_back(best.frame);
    matches.push_back(Outcome(static_cast<std::int32_t>(i), best.frame, best.score));
  }
  centralized_ = EvaluatePr(matches, paper.deployment().trajectory.positions, paper.evaluation().radius_m,
                            paper.relevant());
}

BowEvaluator::Best BowEvaluator::Search(std::int32_t i, const BowVector& part, std::vector<double>& acc,
                                        std::vector<std::int32_t>& touched, std::int64_t& visited) const {
  const int window = paper_.evaluation().suppression_frames;
  // Raw pointers and a local count: through the vectors, every store to `touched` made the
  // compiler reload `acc`'s data and `visited` for each posting.
  if (touched.size() < acc.size()) touched.resize(acc.size());  // once: a frame is touched at most once
  double* const sums = acc.data();
  std::int32_t* const first = touched.data();
  std::int32_t* last = first;
  std::int64_t count = 0;
  const auto add = [&](const BowEntry& q, const Posting& p) {
    double& a = sums[static_cast<std::size_t>(p.frame)];
    if (a == 0.0) *last++ = p.frame;
    a += std::min(static_cast<double>(q.weight), static_cast<double>(p.weight));
  };
  const auto before = [](const Posting& p, std::int32_t frame) { return p.frame < frame; };
  // Each query word's start and postings are reads from memory that miss the cache (the words
  // are spread over a vocabulary of up to 10^7): ask for those of words a few ahead while adding
  // these, so the reads overlap.
  constexpr std::size_t kAhead = 8;
  const auto run = [&](std::size_t k) {
    const auto w = static_cast<std::size_t>(part[k].word);
    return std::pair(postings_.data() + starts_[w], postings_.data() + starts_[w + 1]);
  };
  for (std::size_t k = 0; k < part.size(); ++k) {
    if (k + 2 * kAhead < part.size()) __builtin_prefetch(&starts_[static_cast<std::size_t>(part[k + 2 * kAhead].word)]);
    if (k + kAhead < part.size()) {
      const auto [b, e] = run(k + kAhead);
      __builtin_prefetch(b + (e - b) / 2);  // where the search for the window starts
    }
    const BowEntry& q = part[k];
    // A landmark's word is mostly seen by frames near the query, inside the suppression window:
    // the postings are in frame order, so the window is one run of them, skipped whole (the
    // frames outside are visited in the same order as one by one, so the sums are the same).
    const auto [begin, end] = run(k);
    const Posting* lo = std::lower_bound(begin, end, i - window, before);
    const Posting* hi = std::lower_bound(lo, end, i + window + 1, before);
    for (const Posting* p = begin; p != lo; ++p) add(q, *p);
    for (const Posting* p = hi; p != end; ++p) add(q, *p);
    count += (lo - begin) + (end - hi);
  }
  visited += count;
  Best best;
  for (const std::int32_t* t = first; t != last; ++t) {
    const std::int32_t j = *t;
    double& a = acc[static_cast<std::size_t>(j)];
    if (a > best.score || (a == best.score && j < best.frame)) best = {j, a};
    a = 0.0;
  }
  return best;
}

BowRunResult BowEvaluator::Evaluate(const WordOwners& owners, const std::string& name, bool keep_curve) const {
  const std::vector<BowVector>& frames = bow_.frames;
  const int n = owners.robots();
  const SequenceSplit split = SplitSequence(static_cast<int>(frames.size()), n);
  BowRunResult out;
  std::vector<std::int64_t> searches(static_cast<std::size_t>(n), 0), comparisons = searches, stored = searches;
  std::vector<double> acc(frames.size(), 0.0);
  std::vector<std::int32_t> touched;
  std::vector<MatchOutcome> matches;
  std::int64_t words = 0, part_words = 0;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const auto fi = static_cast<std::int32_t>(i);
    const std::vector<BowVector> parts = owners.Split(frames[i]);
    std::vector<PartialMatch> answers;
    for (int r = 0; r < n; ++r) {
      const BowVector& part = parts[static_cast<std::size_t>(r)];
      if (part.empty()) continue;
      const auto ur = static_cast<std::size_t>(r);
      ++searches[ur];
      ++stored[ur];
      if (split.owner[i].value != r) {
        ++out.part_sizes[EncodedBowQueryBytes(part)];
        part_words += static_cast<std::int64_t>(part.size());
      }
      const Best best = Search(fi, part, acc, touched, comparisons[ur]);
      if (best.frame >= 0) {
        answers.push_back({RobotId(r), split.owner[static_cast<std::size_t>(best.frame)], FrameId(best.frame), best.score});
      }
    }
    words += static_cast<std::int64_t>(frames[i].size());
    const std::optional<VotedMatch> voted = Vote(answers);
    matches.push_back(Outcome(fi, voted ? voted->frame.value : -1, voted ? voted->score : 0.0));
    if (voted) {
      ++out.bow.voted;
      if (voted->frame.value != central_best_[i]) ++out.bow.vote_not_centralized;
    }
  }
  PrResult pr = EvaluatePr(matches, paper_.deployment().trajectory.positions, paper_.evaluation().radius_m,
                           paper_.relevant());
  out.matches = std::move(matches);
  paper_.FillResult(name, std::move(pr), searches, comparisons, stored, keep_curve, out.paper);
  out.paper.row.auc_reference = centralized_.auc;
  out.paper.row.relative_auc = RelativeAuc(out.paper.row.auc, centralized_.auc);
  for (const auto& [bytes, count] : out.part_sizes) {
    out.bow.partial_queries += count;
    out.bow.payload_bytes += bytes * count;
  }
  out.bow.queries = static_cast<std::int64_t>(frames.size());
  out.bow.mean_words = static_cast<double>(words) / static_cast<double>(frames.size());
  if (out.bow.partial_queries > 0) {
    out.bow.mean_part_words = static_cast<double>(part_words) / static_cast<double>(out.bow.partial_queries);
  }
  FillQuantiles(out.part_sizes, out.bow);
  out.paper.row.messages = out.bow.partial_queries;
  out.paper.row.payload_bytes = out.bow.payload_bytes;
  return out;
}

BowRunResult BowEvaluator::EvaluateShared(const WordOwners& owners, const std::string& name) const {
  Fnv1a hash;  // of the vocabulary and every word's owner
  hash.AddValue(owners.vocabulary());
  for (std::int32_t w = 0; w < owners.vocabulary(); ++w) hash.AddValue(owners.OwnerOf(w).value);
  const auto digest = static_cast<std::uint64_t>(hash.value());
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
  std::int64_t words = 0;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    words += static_cast<std::int64_t>(frames[i].size());
    if (central_best_[i] >= 0) ++out.bow.voted;
    if (broadcast) out.part_sizes[EncodedBowQueryBytes(frames[i])] += robots - 1;
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
