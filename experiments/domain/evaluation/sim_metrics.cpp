#include "experiments/domain/evaluation/sim_metrics.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numeric>
#include <stdexcept>
#include <string>
#include <unordered_map>

#include "experiments/domain/evaluation/ground_truth.h"

namespace dvpr {

LatencyStats ComputeLatency(const std::vector<QueryRecord>& queries) {
  LatencyStats stats;
  std::vector<std::int64_t> ns;
  ns.reserve(queries.size());
  for (const auto& q : queries) {
    if (q.latency) {
      ns.push_back(q.latency->ns());
    } else {
      ++stats.incomplete;
    }
  }
  stats.complete = static_cast<std::int64_t>(ns.size());
  if (ns.empty()) return stats;
  std::sort(ns.begin(), ns.end());
  // Sum in integer nanoseconds: exact, so the mean does not depend on order.
  const auto total = std::accumulate(ns.begin(), ns.end(), std::int64_t{0});
  stats.mean_ms = static_cast<double>(total) / static_cast<double>(ns.size()) * 1e-6;
  const auto rank = static_cast<std::size_t>(std::ceil(0.99 * static_cast<double>(ns.size())));
  stats.p99_ms = static_cast<double>(ns[std::max<std::size_t>(rank, 1) - 1]) * 1e-6;
  return stats;
}

namespace {

// Frames bucketed in cubes of side `radius`: every frame within the radius of
// a point lies in the 27 cubes around it, so a relevance test costs the
// frames nearby instead of the whole sequence (100 000-frame runs).
class PositionGrid {
 public:
  PositionGrid(const Positions& p, double radius) : p_(p), cell_(radius > 0 ? radius : 1.0) {
    for (Eigen::Index j = 0; j < p.rows(); ++j) cells_[Key(Cell(j, 0), Cell(j, 1), Cell(j, 2))].push_back(j);
  }
  template <typename Fn>  // fn(j) -> true to stop
  bool AnyNear(Eigen::Index i, Fn&& fn) const {
    const std::int64_t cx = Cell(i, 0), cy = Cell(i, 1), cz = Cell(i, 2);
    for (std::int64_t dx = -1; dx <= 1; ++dx)
      for (std::int64_t dy = -1; dy <= 1; ++dy)
        for (std::int64_t dz = -1; dz <= 1; ++dz) {
          const auto it = cells_.find(Key(cx + dx, cy + dy, cz + dz));
          if (it == cells_.end()) continue;
          for (Eigen::Index j : it->second)
            if (fn(j)) return true;
        }
    return false;
  }

 private:
  std::int64_t Cell(Eigen::Index i, int axis) const {
    return static_cast<std::int64_t>(std::floor(p_(i, axis) / cell_));
  }
  static std::uint64_t Key(std::int64_t x, std::int64_t y, std::int64_t z) {
    const auto h = [](std::int64_t v) { return static_cast<std::uint64_t>(v) * 0x9E3779B97F4A7C15ull; };
    return h(x) ^ (h(y) >> 21) ^ (h(z) << 17) ^ static_cast<std::uint64_t>(z);
  }
  const Positions& p_;
  double cell_;
  std::unordered_map<std::uint64_t, std::vector<Eigen::Index>> cells_;
};
}  // namespace

OnlineTruth ComputeOnlineTruth(const std::vector<QueryRecord>& queries, const Positions& positions,
                               const std::vector<SimTime>& capture_time, const std::vector<RobotId>& taker,
                               double radius_m, const FrameWindow& window) {
  if (taker.size() != capture_time.size() || static_cast<Eigen::Index>(taker.size()) != positions.rows()) {
    throw std::invalid_argument("ComputeOnlineTruth: " + std::to_string(positions.rows()) + " positions, " +
                                std::to_string(capture_time.size()) + " capture times and " +
                                std::to_string(taker.size()) + " takers");
  }
  const double r2 = radius_m * radius_m;
  const PositionGrid grid(positions, radius_m);
  OnlineTruth truth;
  truth.relevant.resize(queries.size());
  truth.correct.resize(queries.size());
  truth.query_class.resize(queries.size(), QueryClass::kNotRelevant);
  for (std::size_t q = 0; q < queries.size(); ++q) {
    const Eigen::Index i = queries[q].frame.value;
    const SimTime t = capture_time[static_cast<std::size_t>(i)];
    const FrameInterval skip = window.Around(i);
    const RobotId robot = taker[static_cast<std::size_t>(i)];
    bool other = false;  // a true match another robot took
    if (queries[q].best) {
      const Eigen::Index m = queries[q].best->frame.value;
      truth.correct[q] = SquaredDistance(positions, i, m) < r2;
      other = truth.correct[q] && taker[static_cast<std::size_t>(m)] != robot;
    }
    bool own = false;
    // Stops at the first frame of another robot (the class is then known), else looks at all.
    grid.AnyNear(i, [&](Eigen::Index j) {
      if (!skip.Contains(j) && capture_time[static_cast<std::size_t>(j)] <= t &&
          SquaredDistance(positions, i, j) < r2) {
        (taker[static_cast<std::size_t>(j)] == robot ? own : other) = true;
      }
      return other;
    });
    truth.relevant[q] = truth.correct[q] || own || other;
    if (truth.relevant[q]) truth.query_class[q] = other ? QueryClass::kInterRobot : QueryClass::kIntraRobot;
  }
  return truth;
}

MatchOutcome OutcomeOf(const QueryRecord& q) {
  MatchOutcome o;
  o.query = q.frame;
  if (q.best) {
    o.match = q.best->frame;
    o.score = q.best->distance;
  }
  return o;
}

const char* QueryClassName(QueryClass c) {
  switch (c) {
    case QueryClass::kInterRobot: return "inter";
    case QueryClass::kIntraRobot: return "intra";
    case QueryClass::kNotRelevant: break;
  }
  return "";
}

ClosureStats ComputeClosures(const std::vector<QueryRecord>& queries, const OnlineTruth& truth,
                             const Positions& positions, const std::vector<RobotId>& taker, double radius_m,
                             int robots) {
  if (truth.query_class.size() != queries.size()) {
    throw std::invalid_argument("ComputeClosures: the truth of " + std::to_string(truth.query_class.size()) +
                                " queries for " + std::to_string(queries.size()));
  }
  ClosureStats s;
  std::vector<MatchOutcome> inter, intra;
  std::vector<std::optional<SimTime>> first(static_cast<std::size_t>(robots) * static_cast<std::size_t>(robots));
  for (std::size_t q = 0; q < queries.size(); ++q) {
    const QueryRecord& r = queries[q];
    if (truth.query_class[q] == QueryClass::kInterRobot) {
      ++s.inter_queries;
      s.inter_recognised += truth.correct[q] ? 1 : 0;
      inter.push_back(OutcomeOf(r));
    } else if (truth.query_class[q] == QueryClass::kIntraRobot) {
      ++s.intra_queries;
      s.intra_recognised += truth.correct[q] ? 1 : 0;
      intra.push_back(OutcomeOf(r));
    }
    if (!r.verify_requested || !r.best) continue;
    const int a = taker[static_cast<std::size_t>(r.frame.value)].value;
    const int b = taker[static_cast<std::size_t>(r.best->frame.value)].value;
    if (a == b) continue;
    ++s.inter_candidates;
    if (!r.verify_accepted.value_or(false)) continue;
    ++s.inter_closures;
    std::optional<SimTime>& f = first[static_cast<std::size_t>(std::min(a, b) * robots + std::max(a, b))];
    if (!f || r.sent < *f) f = r.sent;
  }
  s.inter_auc = EvaluatePr(inter, positions, radius_m, s.inter_queries).auc;
  s.intra_auc = EvaluatePr(intra, positions, radius_m, s.intra_queries).auc;
  for (int a = 0; a < robots; ++a) {
    for (int b = a + 1; b < robots; ++b) {
      s.pairs.push_back({RobotId(a), RobotId(b), first[static_cast<std::size_t>(a * robots + b)]});
    }
  }
  return s;
}

std::optional<SimTime> MedianFirstClosure(const std::vector<PairClosure>& pairs) {
  std::vector<std::int64_t> ns;
  for (const PairClosure& p : pairs) {
    if (p.first) ns.push_back(p.first->ns());
  }
  if (ns.empty()) return std::nullopt;
  std::sort(ns.begin(), ns.end());
  const std::size_t m = ns.size() / 2;
  return SimTime::Nanos(ns.size() % 2 == 1 ? ns[m] : (ns[m - 1] + ns[m]) / 2);
}

}  // namespace dvpr
