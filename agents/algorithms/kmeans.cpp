#include "agents/algorithms/kmeans.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <numeric>
#include <stdexcept>
#include <string>

#if defined(__AVX2__)
#include <immintrin.h>
#endif

#include "agents/algorithms/kmeans_dots.h"
#include "agents/algorithms/l2.h"
#include "sim/random_bits.h"

namespace dvpr {

void KMeansParams::Validate() const {
  if (k < 1) throw std::invalid_argument("KMeansParams.k must be >= 1, got " + std::to_string(k));
  if (max_iterations < 1) {
    throw std::invalid_argument("KMeansParams.max_iterations must be >= 1, got " +
                                std::to_string(max_iterations));
  }
  if (!(tolerance >= 0.0) || !std::isfinite(tolerance)) {
    throw std::invalid_argument("KMeansParams.tolerance must be finite and >= 0");
  }
  if (restarts < 1) {
    throw std::invalid_argument("KMeansParams.restarts must be >= 1, got " +
                                std::to_string(restarts));
  }
}

namespace {

using EigenIndex = Eigen::Index;
using SumMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
constexpr EigenIndex kBlockRows = 512;  // rows per GEMM block: the block stays in L2 while reduced

struct Points {
  const DescriptorMatrix& x;
  Eigen::VectorXf norms;  // ||x_i||^2
};

// EigenIndex drawn with probability weight[i] / sum(weight); sum > 0.
EigenIndex DrawWeighted(const std::vector<double>& weight, double total, Xoshiro256& rng) {
  const double target = rng.Uniform() * total;
  double cumulative = 0;
  EigenIndex last_positive = 0;
  for (std::size_t i = 0; i < weight.size(); ++i) {
    if (weight[i] <= 0) continue;
    cumulative += weight[i];
    last_positive = static_cast<EigenIndex>(i);
    if (cumulative > target) return last_positive;
  }
  return last_positive;  // rounding left target just above the running sum
}

// Squared distance of every point to `center`, min-ed into `nearest`.
void UpdateNearest(const Points& p, const Eigen::RowVectorXf& center, std::vector<double>& nearest) {
  const Eigen::VectorXf dots = p.x * center.transpose();
  const float cn = center.squaredNorm();
  for (EigenIndex i = 0; i < p.x.rows(); ++i) {
    const double d = std::max(0.0f, p.norms[i] - 2.0f * dots[i] + cn);
    nearest[static_cast<std::size_t>(i)] = std::min(nearest[static_cast<std::size_t>(i)], d);
  }
}

// k-means++ (Arthur, Vassilvitskii 2007): first centre uniform, each next one drawn with
// probability proportional to the squared distance to the nearest centre chosen so far.
CentroidMatrix SeedPlusPlus(const Points& p, int k, Xoshiro256& rng) {
  const EigenIndex n = p.x.rows();
  CentroidMatrix centers(k, p.x.cols());
  std::vector<double> nearest(static_cast<std::size_t>(n), std::numeric_limits<double>::infinity());
  EigenIndex chosen = static_cast<EigenIndex>(rng.Below(static_cast<std::uint64_t>(n)));
  for (int c = 0; c < k; ++c) {
    centers.row(c) = p.x.row(chosen);
    if (c + 1 == k) break;
    UpdateNearest(p, centers.row(c), nearest);
    const double total = std::accumulate(nearest.begin(), nearest.end(), 0.0);
    // All points coincide with a centre: any point will do; the duplicate centre's cluster
    // comes out empty and is re-seeded by Lloyd.
    chosen = total > 0 ? DrawWeighted(nearest, total, rng)
                       : static_cast<EigenIndex>(rng.Below(static_cast<std::uint64_t>(n)));
  }
  return centers;
}

struct Assignment {
  std::vector<int> labels;
  std::vector<float> distance;  // squared distance to the assigned centroid (full passes only)
  std::vector<double> upper;    // Hamerly: >= distance to the assigned centroid (not squared)
  std::vector<double> lower;    // Hamerly: <= distance to every other centroid
  SumMatrix sums;               // per cluster, sum of its points (double: order-independent enough)
  std::vector<EigenIndex> counts;
  double inertia = 0;
  EigenIndex changed = 0;            // points whose label differs from the previous assignment
};

// The lowest score (its first index: ties go to the lower centroid) and the second lowest (equal
// to the lowest when two tie) of the centroid scores cn[c] - 2 dots[c] (2 dots is exact, so a
// fused multiply-add gives the same score). No branch on the data: which centroid is nearest is
// a coin flip for the points near a boundary, the very points measured here, and a mispredicted
// search loop cost more than the scan.
struct NearestPair {
  int best;
  float best_score;
  float second_score;
};

NearestPair NearestTwoScalar(const float* cn, const float* dots, EigenIndex k) {
  NearestPair n{0, std::numeric_limits<float>::infinity(), std::numeric_limits<float>::infinity()};
  for (EigenIndex c = 0; c < k; ++c) {
    const float score = cn[c] - 2.0f * dots[c];
    const bool better = score < n.best_score;  // strict: an equal score keeps the lower index
    n.second_score = better ? n.best_score : std::min(n.second_score, score);
    n.best = better ? static_cast<int>(c) : n.best;
    n.best_score = better ? score : n.best_score;
  }
  return n;
}

#if defined(__AVX2__)
constexpr EigenIndex kVectorNearestMax = 64;  // centroids the vector scan takes (8 registers of 8)

float LowestLane(__m256 v) {
  __m128 m = _mm_min_ps(_mm256_castps256_ps128(v), _mm256_extractf128_ps(v, 1));
  m = _mm_min_ps(m, _mm_movehl_ps(m, m));
  return _mm_cvtss_f32(_mm_min_ss(m, _mm_shuffle_ps(m, m, 1)));
}

// The same pair with 8 scores a step: the minimum of a set does not depend on the order it is
// taken in (up to the sign of a zero, which no later sum can tell), and the first index holding
// it is the lowest set bit of the equality mask.
NearestPair NearestTwo(const float* cn, const float* dots, EigenIndex k) {
  if (k > kVectorNearestMax) return NearestTwoScalar(cn, dots, k);
  alignas(32) float scores[kVectorNearestMax];
  const __m256 inf = _mm256_set1_ps(std::numeric_limits<float>::infinity());
  const __m256i lane = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
  const EigenIndex chunks = (k + 7) / 8;
  __m256 low = inf;
  for (EigenIndex j = 0; j < chunks; ++j) {
    const __m256i in = _mm256_cmpgt_epi32(_mm256_set1_epi32(static_cast<int>(k - 8 * j)), lane);
    const __m256 d = _mm256_maskload_ps(dots + 8 * j, in);
    const __m256 score = _mm256_sub_ps(_mm256_maskload_ps(cn + 8 * j, in), _mm256_add_ps(d, d));
    const __m256 kept = _mm256_blendv_ps(inf, score, _mm256_castsi256_ps(in));
    _mm256_store_ps(scores + 8 * j, kept);
    low = _mm256_min_ps(low, kept);
  }
  const __m256 lowest = _mm256_set1_ps(LowestLane(low));
  std::uint64_t at = 0;
  for (EigenIndex j = 0; j < chunks; ++j) {
    const __m256 equal = _mm256_cmp_ps(_mm256_load_ps(scores + 8 * j), lowest, _CMP_EQ_OQ);
    at |= static_cast<std::uint64_t>(static_cast<unsigned>(_mm256_movemask_ps(equal))) << (8 * j);
  }
  NearestPair n{__builtin_ctzll(at), 0, 0};
  n.best_score = scores[n.best];
  const __m256i best = _mm256_set1_epi32(n.best);
  __m256 second = inf;
  for (EigenIndex j = 0; j < chunks; ++j) {  // every score but the best's
    const __m256i index = _mm256_add_epi32(lane, _mm256_set1_epi32(static_cast<int>(8 * j)));
    const __m256 is_best = _mm256_castsi256_ps(_mm256_cmpeq_epi32(index, best));
    second = _mm256_min_ps(second, _mm256_blendv_ps(_mm256_load_ps(scores + 8 * j), inf, is_best));
  }
  n.second_score = LowestLane(second);
  return n;
}
#else
NearestPair NearestTwo(const float* cn, const float* dots, EigenIndex k) { return NearestTwoScalar(cn, dots, k); }
#endif

// The points of one group (agents/algorithms/kmeans_dots.h), scored with the exact kernel: per lane,
// NearestTwo's pair. `on`: the kernel gives Eigen's products for this fit's k and d (checked
// once per fit); otherwise every product is Eigen's.
struct GroupScores {
  bool on = false;
  alignas(64) float xt[kMaxDotsDim * kGroupPoints];
  std::vector<float> dots;  // k x kGroupPoints
  NearestPair nearest[kGroupPoints];
};

#if DVPR_KMEANS_DOTS
// NearestTwoScalar for each lane of a group's dots, 8 lanes a register, centroid by centroid in
// index order with the same strict comparison.
void NearestOfGroup(const float* cn, const float* dots, EigenIndex k, NearestPair* out) {
  const __m256 inf = _mm256_set1_ps(std::numeric_limits<float>::infinity());
  for (int half = 0; half < kGroupPoints; half += 8) {
    __m256 best = inf, second = inf, best_c = _mm256_setzero_ps();
    for (EigenIndex c = 0; c < k; ++c) {
      const __m256 d = _mm256_loadu_ps(dots + kGroupPoints * c + half);
      const __m256 score = _mm256_sub_ps(_mm256_set1_ps(cn[c]), _mm256_add_ps(d, d));
      const __m256 better = _mm256_cmp_ps(score, best, _CMP_LT_OQ);
      second = _mm256_blendv_ps(_mm256_min_ps(second, score), best, better);
      best_c = _mm256_blendv_ps(best_c, _mm256_set1_ps(static_cast<float>(c)), better);
      best = _mm256_blendv_ps(best, score, better);
    }
    alignas(32) float b[8], s[8], i[8];
    _mm256_store_ps(b, best), _mm256_store_ps(s, second), _mm256_store_ps(i, best_c);
    for (int l = 0; l < 8; ++l) out[half + l] = NearestPair{static_cast<int>(i[l]), b[l], s[l]};
  }
}
#else
void NearestOfGroup(const float*, const float*, EigenIndex, NearestPair*) {}
#endif

// Scores `count` points (rows[0..count), count <= kGroupPoints) into g.nearest.
void ScoreGroup(const CentroidMatrix& centers, const Eigen::VectorXf& cn, const float* const* rows, int count,
                GroupScores& g) {
  const EigenIndex k = centers.rows();
  g.dots.resize(static_cast<std::size_t>(k * kGroupPoints));
  TransposeGroup(rows, count, centers.cols(), g.xt);
  GroupDots(g.xt, centers.cols(), centers.data(), k, g.dots.data());
  NearestOfGroup(cn.data(), g.dots.data(), k, g.nearest);
}

// Whether the exact kernel gives Eigen's product for these points and centroids: DotsReplicable
// says so for the build and the shapes; the first points are checked against Eigen on this
// machine (its caches size Eigen's blocks).
bool GroupScoresMatchEigen(const DescriptorMatrix& x, const CentroidMatrix& centers, GroupScores& g) {
  const EigenIndex k = centers.rows();
  const EigenIndex n = std::min<EigenIndex>(kGroupPoints, x.rows());
  if (!DotsReplicable(k, x.cols()) || n < 4) return false;
  DistanceMatrix want(n, k);
  want.noalias() = x.topRows(n) * centers.transpose();
  const float* rows[kGroupPoints];
  for (EigenIndex r = 0; r < n; ++r) rows[r] = x.row(r).data();
  g.dots.resize(static_cast<std::size_t>(k * kGroupPoints));
  TransposeGroup(rows, static_cast<int>(n), x.cols(), g.xt);
  GroupDots(g.xt, x.cols(), centers.data(), k, g.dots.data());
  for (EigenIndex r = 0; r < n / 4 * 4; ++r) {
    for (EigenIndex c = 0; c < k; ++c) {
      if (std::memcmp(&g.dots[static_cast<std::size_t>(kGroupPoints * c + r)], &want(r, c), sizeof(float)) != 0) {
        return false;
      }
    }
  }
  return true;
}

// Point i's nearest centroid in a full pass: its label, distance, bounds and sums.
void AssignPoint(const Points& p, EigenIndex i, const NearestPair& n, Assignment& a) {
  auto& label = a.labels[static_cast<std::size_t>(i)];
  a.changed += (label != n.best);
  label = n.best;
  const float dist = std::max(0.0f, p.norms[i] + n.best_score);
  a.distance[static_cast<std::size_t>(i)] = dist;
  a.upper[static_cast<std::size_t>(i)] = std::sqrt(static_cast<double>(dist));
  a.lower[static_cast<std::size_t>(i)] = std::sqrt(static_cast<double>(std::max(0.0f, p.norms[i] + n.second_score)));
  a.inertia += dist;
  a.sums.row(n.best) += p.x.row(i).cast<double>();
  ++a.counts[static_cast<std::size_t>(n.best)];
}

// Nearest centroid of every point (ties to the lowest index) and the per-cluster sums, in one
// pass over the points, a block of rows at a time: the products Eigen's GEMM would make on each
// block, the points in full groups of 4 columns by the exact kernel (when g.on), the last
// (rows mod 4) by Eigen with 4 points before them (which puts them on their path in the block's
// product), reduced while in cache.
void Assign(const Points& p, const CentroidMatrix& centers, Assignment& a, GroupScores& g) {
  const EigenIndex n = p.x.rows();
  const EigenIndex k = centers.rows();
  const Eigen::VectorXf cn = SquaredNorms(centers);
  a.sums.setZero(k, p.x.cols());
  a.counts.assign(static_cast<std::size_t>(k), 0);
  a.inertia = 0;
  a.changed = 0;
  DistanceMatrix dots;
  for (EigenIndex first = 0; first < n; first += kBlockRows) {
    const EigenIndex rows = std::min(kBlockRows, n - first);
    const EigenIndex grouped = g.on ? rows / 4 * 4 : 0;
    for (EigenIndex r = 0; r < grouped; r += kGroupPoints) {
      const int count = static_cast<int>(std::min<EigenIndex>(kGroupPoints, grouped - r));
      const float* row[kGroupPoints];
      for (int l = 0; l < count; ++l) row[l] = p.x.row(first + r + l).data();
      ScoreGroup(centers, cn, row, count, g);
      for (int l = 0; l < count; ++l) AssignPoint(p, first + r + l, g.nearest[l], a);
    }
    if (grouped == rows) continue;
    const EigenIndex from = grouped == 0 ? 0 : grouped - 4;
    dots.resize(rows - from, k);
    dots.noalias() = p.x.middleRows(first + from, rows - from) * centers.transpose();
    for (EigenIndex r = grouped; r < rows; ++r) AssignPoint(p, first + r, NearestTwo(cn.data(), dots.row(r - from).data(), k), a);
  }
}

// Moves the farthest points (from their own centroid) into the empty clusters.
int RelocateEmpty(const Points& p, Assignment& a) {
  std::vector<int> empty;
  for (std::size_t c = 0; c < a.counts.size(); ++c) {
    if (a.counts[c] == 0) empty.push_back(static_cast<int>(c));
  }
  if (empty.empty()) return 0;
  std::vector<EigenIndex> order(a.labels.size());
  std::iota(order.begin(), order.end(), EigenIndex{0});
  std::stable_sort(order.begin(), order.end(), [&](EigenIndex l, EigenIndex r) {
    return a.distance[static_cast<std::size_t>(l)] > a.distance[static_cast<std::size_t>(r)];
  });
  std::size_t next = 0;
  for (int c : empty) {
    while (next < order.size() &&
           a.counts[static_cast<std::size_t>(a.labels[static_cast<std::size_t>(order[next])])] < 2) {
      ++next;  // taking the only point of a cluster would just move the hole
    }
    if (next == order.size()) break;  // fewer distinct points than clusters: stays empty
    const EigenIndex i = order[next++];
    auto& label = a.labels[static_cast<std::size_t>(i)];
    a.sums.row(label) -= p.x.row(i).cast<double>();
    --a.counts[static_cast<std::size_t>(label)];
    a.sums.row(c) = p.x.row(i).cast<double>();
    a.counts[static_cast<std::size_t>(c)] = 1;
    label = c;
  }
  return static_cast<int>(empty.size());
}

// Mean over dimensions of the per-dimension variance, in one streaming pass (no double copy, no
// allocation per row). A float's square is exact in double, so the sums do not depend on how
// the square is formed.
double MeanVariance(const DescriptorMatrix& x) {
  Eigen::RowVectorXd sum = Eigen::RowVectorXd::Zero(x.cols());
  Eigen::RowVectorXd sum_sq = Eigen::RowVectorXd::Zero(x.cols());
  for (EigenIndex i = 0; i < x.rows(); ++i) {
    const float* row = x.row(i).data();
    for (EigenIndex j = 0; j < x.cols(); ++j) {
      const double v = row[j];
      sum[j] += v;
      sum_sq[j] += v * v;
    }
  }
  const double n = static_cast<double>(x.rows());
  return (sum_sq / n - (sum / n).cwiseProduct(sum / n)).mean();
}

// Half the distance from each centroid to its nearest other centroid: a point closer than that
// to its own centroid cannot be closer to any other (Hamerly 2010).
std::vector<double> HalfGaps(const CentroidMatrix& centers) {
  const EigenIndex k = centers.rows();
  std::vector<double> gap(static_cast<std::size_t>(k), std::numeric_limits<double>::infinity());
  for (EigenIndex c = 0; c < k; ++c) {
    for (EigenIndex o = 0; o < k; ++o) {
      if (o == c) continue;
      const double d = std::sqrt(static_cast<double>((centers.row(c) - centers.row(o)).squaredNorm()));
      gap[static_cast<std::size_t>(c)] = std::min(gap[static_cast<std::size_t>(c)], 0.5 * d);
    }
  }
  return gap;
}

// Points gathered for one product of the bounded pass. The blocks are exactly those the pass has
// always multiplied (the points to re-measure, in index order, cut every kBlockRows), so each
// product and its rounding are unchanged: Eigen's GEMM sums a row differently depending on where
// it falls in its block (agents/algorithms/kmeans_dots.h), and one such row decides a label in the paper sweep.
struct Gathered {
  std::vector<EigenIndex> index;   // kBlockRows slots; the first `size` are in use
  EigenIndex size = 0;
  DescriptorMatrix rows;      // the rows of an Eigen product, copied together
};

// Gathered point i (its row `x`) scored nearest `n`: Hamerly's bounds from the two scores, and
// the move, with the sums, if its centroid changed.
void TakeNearest(const Points& p, EigenIndex i, const float* x, const NearestPair& n, Assignment& a) {
  const auto ui = static_cast<std::size_t>(i);
  a.upper[ui] = std::sqrt(static_cast<double>(std::max(0.0f, p.norms[i] + n.best_score)));
  a.lower[ui] = std::sqrt(static_cast<double>(std::max(0.0f, p.norms[i] + n.second_score)));
  const int own = a.labels[ui];
  if (n.best == own) return;
  ++a.changed;
  const Eigen::Map<const Eigen::RowVectorXf> row(x, p.x.cols());  // just scored: in cache
  a.sums.row(own) -= row.cast<double>();
  a.sums.row(n.best) += row.cast<double>();
  --a.counts[static_cast<std::size_t>(own)];
  ++a.counts[static_cast<std::size_t>(n.best)];
  a.labels[ui] = n.best;
}

// Nearest and second-nearest centroid of the gathered points, as the block's Eigen product gives
// them (the exact kernel for the points in full groups of 4 columns when s.on, Eigen for the
// rest as in Assign); moves the points that change cluster, with their sums, in index order.
// The rows are read where they are: the pass has just measured them, so they are in cache.
void ReassignGathered(const Points& p, const CentroidMatrix& centers, const Eigen::VectorXf& cn,
                      Gathered& g, DistanceMatrix& dots, GroupScores& s, Assignment& a) {
  const EigenIndex k = centers.rows();
  const EigenIndex grouped = s.on ? g.size / 4 * 4 : 0;
  for (EigenIndex r = 0; r < grouped; r += kGroupPoints) {
    const int count = static_cast<int>(std::min<EigenIndex>(kGroupPoints, grouped - r));
    const float* row[kGroupPoints];
    for (int l = 0; l < count; ++l) row[l] = p.x.row(g.index[static_cast<std::size_t>(r + l)]).data();
    ScoreGroup(centers, cn, row, count, s);
    for (int l = 0; l < count; ++l) TakeNearest(p, g.index[static_cast<std::size_t>(r + l)], row[l], s.nearest[l], a);
  }
  if (grouped < g.size) {
    const EigenIndex from = grouped == 0 ? 0 : grouped - 4;
    g.rows.resize(g.size - from, p.x.cols());
    for (EigenIndex r = from; r < g.size; ++r) g.rows.row(r - from) = p.x.row(g.index[static_cast<std::size_t>(r)]);
    dots.resize(g.size - from, k);
    dots.noalias() = g.rows * centers.transpose();
    for (EigenIndex r = grouped; r < g.size; ++r) {
      const EigenIndex i = g.index[static_cast<std::size_t>(r)];
      TakeNearest(p, i, p.x.row(i).data(), NearestTwo(cn.data(), dots.row(r - from).data(), k), a);
    }
  }
  g.size = 0;
}

// Scratch space of the bounded passes, kept across iterations.
struct BoundsWork {
  std::vector<EigenIndex> suspects;  // points whose stale bounds allow a change (first ones in use)
  Gathered gathered;
  DistanceMatrix dots;
  std::unique_ptr<GroupScores> scores = std::make_unique<GroupScores>();
};

// How far the centroids moved, as Hamerly's bounds need it: a point's upper bound grows by its
// own centroid's move, its lower bound shrinks by the largest move of any other centroid.
struct Moves {
  std::vector<double> own;    // per centroid
  std::vector<double> other;  // per centroid: the largest move among the others
};

Moves BoundMoves(const std::vector<double>& moved) {
  std::size_t far = 0;
  for (std::size_t c = 1; c < moved.size(); ++c) far = moved[c] > moved[far] ? c : far;
  double second = 0;
  for (std::size_t c = 0; c < moved.size(); ++c) second = c == far ? second : std::max(second, moved[c]);
  Moves m{moved, std::vector<double>(moved.size(), moved[far])};
  m.other[far] = second;
  return m;
}

// Loosens the bounds by the moves and lists the points they no longer clear (upper bound above
// both the half gap of their centroid and the lower bound), in index order, in one pass; returns
// how many. `out` holds a slot for every point.
std::size_t Suspects(const Moves& moves, const std::vector<double>& gap, Assignment& a, std::vector<EigenIndex>& out) {
  const auto n = a.labels.size();
  out.resize(n);
  std::size_t count = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const auto own = static_cast<std::size_t>(a.labels[i]);
    const double upper = a.upper[i] += moves.own[own];
    const double lower = a.lower[i] -= moves.other[own];
    out[count] = static_cast<EigenIndex>(i);
    count += upper > std::max(gap[own], lower);  // no branch: a suspect is a coin flip
  }
  return count;
}

// Asks the memory for the rows of point `i` ahead of their use: the points to re-measure are
// scattered over the 20 000 x 512-byte rows, and their loads, one after the other, were most
// of the pass's time.
void PrefetchRow(const DescriptorMatrix& x, EigenIndex i) {
  const char* row = reinterpret_cast<const char*>(x.data() + i * x.cols());
  const EigenIndex bytes = x.cols() * static_cast<EigenIndex>(sizeof(float));
  for (EigenIndex b = 0; b < bytes; b += 64) __builtin_prefetch(row + b);
}

// One Hamerly assignment pass: only points whose bounds cannot exclude a change are measured,
// and the sums follow the points that move. First the stale bounds pick the suspects; then
// each suspect's own distance is measured exactly (rows prefetched a few suspects ahead) and,
// if that does not clear it, the point joins the block to re-measure (its row stays in cache).
void AssignWithBounds(const Points& p, const CentroidMatrix& centers, const Moves& moves, Assignment& a,
                      BoundsWork& w) {
  constexpr std::size_t kAhead = 16;  // suspects prefetched ahead of the one measured
  const std::vector<double> gap = HalfGaps(centers);
  const Eigen::VectorXf cn = SquaredNorms(centers);
  a.changed = 0;
  const std::size_t suspects = Suspects(moves, gap, a, w.suspects);
  Gathered& g = w.gathered;
  g.index.resize(kBlockRows);
  for (std::size_t s = 0; s < suspects; ++s) {
    if (s + kAhead < suspects) PrefetchRow(p.x, w.suspects[s + kAhead]);
    const EigenIndex i = w.suspects[s];
    const auto ui = static_cast<std::size_t>(i);
    const int own = a.labels[ui];
    const double limit = std::max(gap[static_cast<std::size_t>(own)], a.lower[ui]);
    a.upper[ui] = std::sqrt(static_cast<double>((p.x.row(i) - centers.row(own)).squaredNorm()));
    // The point goes into the next free slot, which only a point still in doubt keeps: no
    // branch on a coin flip, and nothing later waits for the count but the next slot's address.
    g.index[static_cast<std::size_t>(g.size)] = i;
    g.size += a.upper[ui] > limit;
    // Re-measuring a block moves only points before the next suspect: its test is unchanged.
    if (g.size == kBlockRows) ReassignGathered(p, centers, cn, g, w.dots, *w.scores, a);
  }
  if (g.size > 0) ReassignGathered(p, centers, cn, g, w.dots, *w.scores, a);
}

// Exact squared distance of every point to its own centroid (for the empty-cluster re-seed).
void OwnDistances(const Points& p, const CentroidMatrix& centers, Assignment& a) {
  for (EigenIndex i = 0; i < p.x.rows(); ++i) {
    a.distance[static_cast<std::size_t>(i)] =
        (p.x.row(i) - centers.row(a.labels[static_cast<std::size_t>(i)])).squaredNorm();
  }
}

// Lloyd's iterations, accelerated with Hamerly's bounds: the same fixed points as plain Lloyd
// (up to float rounding), but late iterations measure only the few points near a boundary.
// `final_pass`: label the points by the final centroids (and sum the inertia), one more full pass.
KMeansResult Lloyd(const Points& p, const KMeansParams& params, std::uint64_t seed,
                   double abs_tolerance, bool final_pass) {
  Xoshiro256 rng(seed);
  KMeansResult result;
  result.centroids = SeedPlusPlus(p, params.k, rng);
  Assignment a;
  const auto n = static_cast<std::size_t>(p.x.rows());
  a.labels.assign(n, -1);
  a.distance.assign(n, 0.0f);
  a.upper.assign(n, 0.0);
  a.lower.assign(n, 0.0);
  bool full = true;  // first pass, and after a re-seed: measure everything with GEMM
  std::vector<double> moved(static_cast<std::size_t>(params.k));
  BoundsWork work;
  GroupScores& scores = *work.scores;
  scores.on = GroupScoresMatchEigen(p.x, result.centroids, scores);
  for (int it = 0; it < params.max_iterations; ++it) {
    if (full) {
      Assign(p, result.centroids, a, scores);
    } else {
      AssignWithBounds(p, result.centroids, BoundMoves(moved), a, work);
    }
    result.iterations = it + 1;
    if (it > 0 && a.changed == 0) {  // same labels, same centroids: a fixed point
      result.converged = true;
      break;
    }
    full = std::find(a.counts.begin(), a.counts.end(), 0) != a.counts.end();
    if (full) {
      OwnDistances(p, result.centroids, a);
      result.empty_cluster_reseeds += RelocateEmpty(p, a);
    }
    double shift = 0;
    for (EigenIndex c = 0; c < result.centroids.rows(); ++c) {
      const auto count = a.counts[static_cast<std::size_t>(c)];
      moved[static_cast<std::size_t>(c)] = 0;
      if (count == 0) continue;  // no point to move it to: keep the old centroid
      const Eigen::RowVectorXf mean = (a.sums.row(c) / static_cast<double>(count)).cast<float>();
      const double step = (mean - result.centroids.row(c)).cast<double>().squaredNorm();
      shift += step;
      moved[static_cast<std::size_t>(c)] = std::sqrt(step);
      result.centroids.row(c) = mean;
    }
    if (shift <= abs_tolerance) {
      result.converged = true;
      break;
    }
  }
  if (!final_pass) return result;
  Assign(p, result.centroids, a, scores);  // labels and inertia of the final centroids
  result.labels = std::move(a.labels);
  result.inertia = a.inertia;
  return result;
}

// KMeansDetailed; without `final_pass` (only the centroids wanted, one restart) the labels and
// inertia stay empty, which saves a full pass over the points.
KMeansResult Fit(const DescriptorMatrix& points, const KMeansParams& params, bool final_pass) {
  params.Validate();
  if (points.rows() < params.k) {
    throw std::invalid_argument("KMeans: " + std::to_string(points.rows()) +
                                " points for k = " + std::to_string(params.k));
  }
  if (!AllFinite(points)) throw std::invalid_argument("KMeans: points contain NaN or Inf");
  const Points p{points, SquaredNorms(points)};
  const double abs_tolerance = params.tolerance * MeanVariance(points);
  KMeansResult best;
  for (int r = 0; r < params.restarts; ++r) {
    KMeansResult run = Lloyd(p, params, MixSeed(params.seed, static_cast<std::uint64_t>(r)),
                             abs_tolerance, final_pass || params.restarts > 1);
    if (r == 0 || run.inertia < best.inertia) best = std::move(run);
  }
  return best;
}

}  // namespace

KMeansResult KMeansDetailed(const DescriptorMatrix& points, const KMeansParams& params) {
  return Fit(points, params, true);
}

CentroidMatrix KMeans(const DescriptorMatrix& points, const KMeansParams& params) {
  return Fit(points, params, false).centroids;  // the restarts' inertia still picks the winner
}

std::vector<int> NearestCentroid(const DescriptorMatrix& points, const CentroidMatrix& centroids) {
  return NearestRows(points, centroids);
}

}  // namespace dvpr
