#include "experiments/protocols/paper/static_strategies.h"

#include <algorithm>
#include <cstdint>
#include <vector>

#include "experiments/domain/data/split.h"

namespace dvpr {

namespace {

// Per frame, the robots as bit sets of `words` 64-bit words: who searches it, who stores it.
struct RoutedFrames {
  int words = 1;
  std::vector<std::uint64_t> search;
  std::vector<std::uint64_t> store;
  std::vector<std::int64_t> searches;             // per robot
  std::vector<std::int64_t> stored;               // per robot
  std::vector<std::vector<std::int32_t>> stores;  // per robot: frames stored there, ascending

  bool Candidate(std::int64_t i, std::int64_t j) const {
    const auto a = static_cast<std::size_t>(i) * static_cast<std::size_t>(words);
    const auto b = static_cast<std::size_t>(j) * static_cast<std::size_t>(words);
    for (int w = 0; w < words; ++w) {
      if (search[a + static_cast<std::size_t>(w)] & store[b + static_cast<std::size_t>(w)]) return true;
    }
    return false;
  }
};

void SetBit(std::vector<std::uint64_t>& bits, std::size_t frame, int words, RobotId r) {
  bits[frame * static_cast<std::size_t>(words) + static_cast<std::size_t>(r.value / 64)] |=
      std::uint64_t{1} << (r.value % 64);
}

RoutedFrames RouteEveryFrame(const Dataset& data, const PlacementStrategy& routing) {
  const DescriptorMatrix& x = data.descriptors;
  const int n = routing.num_robots();
  const SequenceSplit split = TeamSplit(data, n);
  RoutedFrames f;
  f.words = (n + 63) / 64;
  const auto cells = static_cast<std::size_t>(x.rows()) * static_cast<std::size_t>(f.words);
  f.search.assign(cells, 0);
  f.store.assign(cells, 0);
  f.searches.assign(static_cast<std::size_t>(n), 0);
  f.stored.assign(static_cast<std::size_t>(n), 0);
  f.stores.resize(static_cast<std::size_t>(n));
  for (Eigen::Index i = 0; i < x.rows(); ++i) {
    const auto fi = static_cast<std::size_t>(i);
    const PlacementDecision d = routing.Route(split.owner[fi], x.row(i).data());
    for (RobotId r : d.search_at) SetBit(f.search, fi, f.words, r), ++f.searches[static_cast<std::size_t>(r.value)];
    for (RobotId r : d.store_at) {
      SetBit(f.store, fi, f.words, r);
      ++f.stored[static_cast<std::size_t>(r.value)];
      f.stores[static_cast<std::size_t>(r.value)].push_back(static_cast<std::int32_t>(i));
    }
  }
  return f;
}

// Per robot: descriptors its searches compare with (its stored frames outside each window).
std::vector<std::int64_t> Comparisons(const RoutedFrames& f, std::int64_t frames, const FrameWindow& window) {
  std::vector<std::int64_t> comparisons(f.stores.size(), 0);
  for (std::int64_t i = 0; i < frames; ++i) {
    for (std::size_t r = 0; r < f.stores.size(); ++r) {
      const std::size_t bit = static_cast<std::size_t>(i) * static_cast<std::size_t>(f.words) + r / 64;
      if (!(f.search[bit] >> (r % 64) & 1U)) continue;
      const auto& m = f.stores[r];
      const FrameInterval w = window.Around(i);
      const auto in_window = std::upper_bound(m.begin(), m.end(), w.hi) - std::lower_bound(m.begin(), m.end(), w.lo);
      comparisons[r] += static_cast<std::int64_t>(m.size()) - in_window;
    }
  }
  return comparisons;
}

}  // namespace

PaperRunResult EvaluatePlacement(const PaperEvaluator& evaluator, const PlacementStrategy& routing,
                               const std::string& name, bool keep_curve) {
  const Dataset& data = evaluator.deployment();
  const RoutedFrames f = RouteEveryFrame(data, routing);
  PaperRunResult result;
  const auto matches = evaluator.neighbours().BestMatchesWhere(
      [&f](std::int64_t i, std::int64_t j) { return f.Candidate(i, j); }, &result.fallback_scans);
  PrResult pr = EvaluatePr(matches, data.trajectory.positions, evaluator.evaluation().radius_m,
                           evaluator.relevant());
  const std::vector<std::int64_t> comparisons =
      Comparisons(f, data.size(), evaluator.window());
  evaluator.FillResult(name, std::move(pr), f.searches, comparisons, f.stored, keep_curve, result);
  return result;
}

}  // namespace dvpr
