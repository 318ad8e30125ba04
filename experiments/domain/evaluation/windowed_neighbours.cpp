#include "experiments/domain/evaluation/windowed_neighbours.h"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "agents/algorithms/l2.h"
#include "experiments/domain/parallel/parallel_for.h"

namespace dvpr {

namespace {
constexpr std::int64_t kBlockRows = 128;  // rows of D alive at once per thread
constexpr double kInf = std::numeric_limits<double>::infinity();
}  // namespace

WindowedNeighbours::WindowedNeighbours(const DescriptorMatrix& descriptors, const FrameWindow& window,
                                       int list_size, int threads)
    : x_(descriptors), n_(descriptors.rows()), window_(window), list_size_(list_size) {
  if (window.frames() < 0) throw std::invalid_argument("WindowedNeighbours: window < 0");
  if (list_size < 1) throw std::invalid_argument("WindowedNeighbours: list_size must be >= 1");
  if (!AllFinite(descriptors)) {
    throw std::invalid_argument("WindowedNeighbours: descriptors contain NaN or Inf");
  }
  const auto cells = static_cast<std::size_t>(n_) * static_cast<std::size_t>(list_size_);
  frame_.assign(cells, -1);
  distance_.assign(cells, kInf);
  length_.assign(static_cast<std::size_t>(n_), 0);
  complete_below_.assign(static_cast<std::size_t>(n_), kInf);
  const Eigen::VectorXf norms = SquaredNorms(x_);
  const std::int64_t blocks = (n_ + kBlockRows - 1) / kBlockRows;
  ParallelFor(blocks, threads, [&](std::int64_t b) {
    BuildRows(norms, b * kBlockRows, std::min(kBlockRows, n_ - b * kBlockRows));
  });
}

void WindowedNeighbours::BuildRows(const Eigen::VectorXf& norms, std::int64_t first,
                                   std::int64_t count) {
  const float max_norm = norms.maxCoeff();
  DistanceMatrix d;
  SquaredL2Rows(x_, norms, first, count, x_, norms, d);
  std::vector<std::pair<float, std::int32_t>> pool;
  std::vector<std::pair<double, std::int32_t>> exact;
  for (std::int64_t r = 0; r < count; ++r) {
    const std::int64_t i = first + r;
    const FrameInterval skip = window_.Around(i);
    pool.clear();
    for (std::int64_t j = 0; j < n_; ++j) {
      if (skip.Contains(j)) continue;
      pool.emplace_back(d(r, j), static_cast<std::int32_t>(j));
    }
    const auto keep = std::min<std::size_t>(pool.size(), static_cast<std::size_t>(list_size_));
    double bound = kInf;
    if (pool.size() > keep) {
      std::nth_element(pool.begin(), pool.begin() + static_cast<std::ptrdiff_t>(keep), pool.end());
      // Every frame left out has float distance >= pool[keep], so exact >= that - error.
      bound = static_cast<double>(pool[keep].first) -
              static_cast<double>(GemmErrorBound(norms[i], max_norm, x_.cols()));
    }
    exact.clear();
    for (std::size_t e = 0; e < keep; ++e) {
      const std::int32_t j = pool[e].second;
      exact.emplace_back(ExactSquaredL2(x_.row(i).data(), x_.row(j).data(), x_.cols()), j);
    }
    std::sort(exact.begin(), exact.end());  // by (distance, frame): argmin's tie to lowest
    const auto base = static_cast<std::size_t>(i) * static_cast<std::size_t>(list_size_);
    for (std::size_t e = 0; e < keep; ++e) {
      distance_[base + e] = exact[e].first;
      frame_[base + e] = exact[e].second;
    }
    length_[static_cast<std::size_t>(i)] = static_cast<std::int32_t>(keep);
    complete_below_[static_cast<std::size_t>(i)] = bound;
  }
}

std::vector<MatchOutcome> WindowedNeighbours::BestMatches() const {
  std::vector<RobotId> one_pool(static_cast<std::size_t>(n_), RobotId(0));
  return BestMatches(one_pool);
}

MatchOutcome WindowedNeighbours::Scan(std::int64_t i,
                                      const std::vector<std::int32_t>& members) const {
  MatchOutcome out{FrameId(static_cast<std::int32_t>(i)), std::nullopt, 0};
  double best = kInf;
  const FrameInterval skip = window_.Around(i);
  for (std::int32_t j : members) {  // ascending, so strict < keeps the lowest frame on ties
    if (skip.Contains(j)) continue;
    const double dist = ExactSquaredL2(x_.row(i).data(), x_.row(j).data(), x_.cols());
    if (!out.match || dist < best) best = dist, out.match = FrameId(j);
  }
  if (out.match) out.score = best;
  return out;
}

std::vector<MatchOutcome> WindowedNeighbours::BestMatches(std::span<const RobotId> pool,
                                                          std::int64_t* fallbacks) const {
  if (static_cast<std::int64_t>(pool.size()) != n_) {
    throw std::invalid_argument("WindowedNeighbours: " + std::to_string(pool.size()) +
                                " pool labels for " + std::to_string(n_) + " frames");
  }
  for (RobotId label : pool) {
    if (label.value < 0) throw std::invalid_argument("WindowedNeighbours: negative pool label");
  }
  std::vector<std::vector<std::int32_t>> members;  // frames of each pool, built on first need
  std::vector<MatchOutcome> outcomes;
  outcomes.reserve(static_cast<std::size_t>(n_));
  std::int64_t fell_back = 0;
  for (std::int64_t i = 0; i < n_; ++i) {
    const RobotId label = pool[static_cast<std::size_t>(i)];
    const auto base = static_cast<std::size_t>(i) * static_cast<std::size_t>(list_size_);
    const double complete_below = complete_below_[static_cast<std::size_t>(i)];
    MatchOutcome out{FrameId(static_cast<std::int32_t>(i)), std::nullopt, 0};
    bool proven = false;
    for (std::int32_t e = 0; e < length_[static_cast<std::size_t>(i)]; ++e) {
      const std::int32_t j = frame_[base + static_cast<std::size_t>(e)];
      if (pool[static_cast<std::size_t>(j)] != label) continue;
      const double dist = distance_[base + static_cast<std::size_t>(e)];
      if (dist < complete_below) out = {out.query, FrameId(j), dist}, proven = true;
      break;  // the first in the pool is the best in the list; proven only below the bound
    }
    if (!proven && complete_below < kInf) {  // the list is partial and could not decide
      ++fell_back;
      if (members.empty()) {
        for (std::int64_t j = 0; j < n_; ++j) {
          const auto l = static_cast<std::size_t>(pool[static_cast<std::size_t>(j)].value);
          if (l >= members.size()) members.resize(l + 1);
          members[l].push_back(static_cast<std::int32_t>(j));
        }
      }
      out = Scan(i, members[static_cast<std::size_t>(label.value)]);
    }
    outcomes.push_back(out);
  }
  if (fallbacks) *fallbacks = fell_back;
  return outcomes;
}

std::vector<MatchOutcome> WindowedNeighbours::BestMatchesWhere(const CandidateTest& candidate,
                                                               std::int64_t* fallbacks) const {
  std::vector<MatchOutcome> outcomes;
  outcomes.reserve(static_cast<std::size_t>(n_));
  std::int64_t fell_back = 0;
  for (std::int64_t i = 0; i < n_; ++i) {
    const auto base = static_cast<std::size_t>(i) * static_cast<std::size_t>(list_size_);
    const double complete_below = complete_below_[static_cast<std::size_t>(i)];
    MatchOutcome out{FrameId(static_cast<std::int32_t>(i)), std::nullopt, 0};
    bool proven = false;
    for (std::int32_t e = 0; e < length_[static_cast<std::size_t>(i)]; ++e) {
      const std::int32_t j = frame_[base + static_cast<std::size_t>(e)];
      if (!candidate(i, j)) continue;
      const double dist = distance_[base + static_cast<std::size_t>(e)];
      if (dist < complete_below) out = {out.query, FrameId(j), dist}, proven = true;
      break;  // as in BestMatches(pool): the first candidate in the list is the best listed
    }
    if (!proven && complete_below < kInf) {
      ++fell_back;
      double best = kInf;
      const FrameInterval skip = window_.Around(i);
      for (std::int64_t j = 0; j < n_; ++j) {  // ascending: strict < keeps the lowest frame
        if (skip.Contains(j) || !candidate(i, j)) continue;
        const double dist = ExactSquaredL2(x_.row(i).data(), x_.row(j).data(), x_.cols());
        if (!out.match || dist < best) best = dist, out.match = FrameId(static_cast<std::int32_t>(j));
      }
      if (out.match) out.score = best;
    }
    outcomes.push_back(out);
  }
  if (fallbacks) *fallbacks = fell_back;
  return outcomes;
}

}  // namespace dvpr
