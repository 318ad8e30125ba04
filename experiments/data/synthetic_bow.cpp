#include "experiments/data/synthetic_bow.h"

#include "sim/random_bits.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <map>
#include <utility>

namespace dvpr {
namespace {

constexpr double kCell_m = 10.0;  // landmarks are drawn per square cell of this side
// Stream keys, apart from synthetic.cpp's (1..4, 1000+).
constexpr std::uint64_t kLandmarkStream = 0xB0B0'0001ULL;
constexpr std::uint64_t kFeatureStream = 0xB0B0'0002ULL;
// A landmark's viewpoint sectors come from its own key, not from the cell's stream, so that
// view_sector_deg leaves the landmarks (position, word, visibility) of today's world as they were.
constexpr std::uint64_t kSectorKey = 0xB0B0'0003ULL;

struct Landmark {
  double x, z;
  std::int32_t word;    // its word seen from its first viewpoint sector (from every direction by default)
  double omega, phase;  // visibility over time
  std::uint64_t key;    // the other sectors' words and where sector 0 starts (view_sector_deg < 360)
  double sector_start;  // radians
};

double Normal(Xoshiro256& rng) {  // Box-Muller, one value per call (portable across libraries)
  const double u1 = 1.0 - rng.Uniform();
  const double u2 = rng.Uniform();
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

// The landmarks of the world, drawn cell by cell when first looked at.
class LandmarkField {
 public:
  LandmarkField(const SyntheticBowParams& p, const SyntheticParams& a, std::uint64_t seed)
      : p_(p), a_(a), seed_(MixSeed(seed, kLandmarkStream)) {}

  const std::vector<Landmark>& Cell(std::int64_t cx, std::int64_t cz) {
    auto [it, fresh] = cells_.try_emplace({cx, cz});
    if (!fresh) return it->second;
    const std::uint64_t cell_seed =
        MixSeed(MixSeed(seed_, static_cast<std::uint64_t>(cx)), static_cast<std::uint64_t>(cz));
    Xoshiro256 rng(cell_seed);
    const double expected = p_.landmark_density * kCell_m * kCell_m;
    const auto count = static_cast<int>(std::floor(expected + rng.Uniform()));  // mean `expected`
    for (int k = 0; k < count; ++k) {
      Landmark l;
      l.x = (static_cast<double>(cx) + rng.Uniform()) * kCell_m;
      l.z = (static_cast<double>(cz) + rng.Uniform()) * kCell_m;
      l.word = LandmarkWord(rng);
      l.omega = Normal(rng) / a_.appearance_time_scale_frames;
      l.phase = rng.Uniform() * 2.0 * std::numbers::pi;
      l.key = MixSeed(MixSeed(cell_seed, kSectorKey), static_cast<std::uint64_t>(k));
      l.sector_start = p_.view_sector_deg < 360.0 ? Xoshiro256(l.key).Uniform() * 2.0 * std::numbers::pi : 0.0;
      it->second.push_back(l);
    }
    return it->second;
  }

  // The word `l` quantises to seen from `direction` (radians, from the landmark to the camera).
  std::int32_t WordSeenFrom(const Landmark& l, double direction) const {
    if (p_.view_sector_deg >= 360.0) return l.word;
    const double turned = std::fmod(direction - l.sector_start + 4.0 * std::numbers::pi, 2.0 * std::numbers::pi);
    const auto sector = static_cast<std::uint64_t>(std::floor(turned / (p_.view_sector_deg * std::numbers::pi / 180.0)));
    if (sector == 0) return l.word;
    Xoshiro256 rng(MixSeed(l.key, sector));
    return LandmarkWord(rng);
  }

  // Landmarks' words avoid the common ones (with no common words: Below(vocabulary), as ever).
  std::int32_t LandmarkWord(Xoshiro256& rng) const {
    const auto common = static_cast<std::uint64_t>(p_.common_words);
    return static_cast<std::int32_t>(common + rng.Below(static_cast<std::uint64_t>(p_.vocabulary) - common));
  }

 private:
  const SyntheticBowParams& p_;
  const SyntheticParams& a_;
  std::uint64_t seed_;
  // Keyed by the cell itself: a hashed key collided (a cell of x < 0 came back for one of x > 0).
  std::map<std::pair<std::int64_t, std::int64_t>, std::vector<Landmark>> cells_;
};

struct View {
  double x, z, hx, hz, t;
};

// The landmarks `v` sees and their cumulative draw weights.
void Visible(LandmarkField& field, const View& v, const SyntheticBowParams& p, const SyntheticParams& a,
             std::vector<std::int32_t>& words, std::vector<double>& cumulative) {
  words.clear();
  cumulative.clear();
  const double cos_half = std::cos(p.field_of_view_deg * std::numbers::pi / 360.0);
  const auto lo = [&](double c) { return static_cast<std::int64_t>(std::floor((c - p.range_m) / kCell_m)); };
  const auto hi = [&](double c) { return static_cast<std::int64_t>(std::floor((c + p.range_m) / kCell_m)); };
  double total = 0.0;
  for (std::int64_t cx = lo(v.x); cx <= hi(v.x); ++cx) {
    for (std::int64_t cz = lo(v.z); cz <= hi(v.z); ++cz) {
      for (const Landmark& l : field.Cell(cx, cz)) {
        const double dx = l.x - v.x, dz = l.z - v.z, d = std::hypot(dx, dz);
        if (d > p.range_m || (d > 0 && (dx * v.hx + dz * v.hz) / d < cos_half)) continue;
        const double drift = a.appearance_change * std::numbers::sqrt2 * std::cos(l.omega * v.t + l.phase);
        total += std::exp(-d / p.range_m + drift);
        words.push_back(field.WordSeenFrom(l, std::atan2(-dz, -dx)));
        cumulative.push_back(total);
      }
    }
  }
}

View ViewOf(const Trajectory& trajectory, Eigen::Index i) {
  // KITTI's ground plane is x-z, as in SyntheticDeployment.
  const double hx = trajectory.headings(i, 0), hz = trajectory.headings(i, 2);
  const double hn = std::hypot(hx, hz);
  return {trajectory.positions(i, 0), trajectory.positions(i, 2), hn > 0 ? hx / hn : 1.0, hn > 0 ? hz / hn : 0.0,
          static_cast<double>(i)};
}

void Require(bool ok, const char* field, const std::string& why) {
  if (!ok) throw std::invalid_argument(std::string(field) + ": " + why);
}

}  // namespace

void SyntheticBowParams::Validate() const {
  Require(features >= 1 && features <= 100000, "features", "must be in [1, 100000], got " + std::to_string(features));
  Require(vocabulary >= 2 && vocabulary <= 10000000, "vocabulary",
          "must be in [2, 10000000], got " + std::to_string(vocabulary));
  Require(landmark_density > 0 && landmark_density <= 10, "landmark_density", "must be in (0, 10]");
  Require(range_m > 0 && range_m <= 1000, "range_m", "must be in (0, 1000]");
  Require(field_of_view_deg > 0 && field_of_view_deg <= 360, "field_of_view_deg", "must be in (0, 360]");
  Require(common_words >= 0 && common_words < vocabulary, "common_words",
          "must be in [0, vocabulary - 1 = " + std::to_string(vocabulary - 1) + "], got " + std::to_string(common_words));
  Require(common_share >= 0 && common_share <= 1, "common_share", "must be in [0, 1]");
  Require(common_share == 0 || common_words >= 1, "common_share", "needs common_words >= 1 when above 0");
  Require(view_sector_deg > 0 && view_sector_deg <= 360, "view_sector_deg", "must be in (0, 360]");
}

std::vector<std::vector<std::int32_t>> SyntheticBowWords(const Trajectory& trajectory,
                                                         const SyntheticParams& appearance,
                                                         const SyntheticBowParams& params, std::uint64_t seed) {
  params.Validate();
  appearance.Validate();
  LandmarkField field(params, appearance, seed);
  const double noise_share = appearance.noise / (1.0 + appearance.noise);
  const auto vocabulary = static_cast<std::uint64_t>(params.vocabulary);
  const auto common = static_cast<std::uint64_t>(params.common_words);
  const bool aliasing = params.common_share > 0;
  std::vector<std::vector<std::int32_t>> out(static_cast<std::size_t>(trajectory.size()));
  std::vector<std::int32_t> seen;
  std::vector<double> cumulative;
  for (Eigen::Index i = 0; i < trajectory.size(); ++i) {
    Visible(field, ViewOf(trajectory, i), params, appearance, seen, cumulative);
    Xoshiro256 rng(MixSeed(MixSeed(seed, kFeatureStream), static_cast<std::uint64_t>(i)));
    auto& words = out[static_cast<std::size_t>(i)];
    words.reserve(static_cast<std::size_t>(params.features));
    for (int k = 0; k < params.features; ++k) {
      // Without common words no draw is added: today's world keeps its stream.
      if ((seen.empty() && !aliasing) || rng.Uniform() < noise_share) {
        words.push_back(static_cast<std::int32_t>(rng.Below(vocabulary)));
        continue;
      }
      if (aliasing && rng.Uniform() < params.common_share) {
        words.push_back(static_cast<std::int32_t>(rng.Below(common)));
        continue;
      }
      if (seen.empty()) {
        words.push_back(static_cast<std::int32_t>(rng.Below(vocabulary)));
        continue;
      }
      const double u = rng.Uniform() * cumulative.back();
      const auto at = std::upper_bound(cumulative.begin(), cumulative.end(), u) - cumulative.begin();
      words.push_back(seen[static_cast<std::size_t>(std::min<std::ptrdiff_t>(at, std::ssize(seen) - 1))]);
    }
  }
  return out;
}

BowData TfIdfFromWords(const std::vector<std::vector<std::int32_t>>& words, int vocabulary) {
  std::vector<BowVector> tf;
  tf.reserve(words.size());
  for (const auto& w : words) tf.push_back(TermFrequencies(w));
  const std::vector<double> idf = InverseDocumentFrequency(tf, vocabulary);
  BowData data;
  data.vocabulary = vocabulary;
  data.frames.reserve(tf.size());
  for (const BowVector& v : tf) data.frames.push_back(WeightTfIdf(v, idf));
  return data;
}

BowData SyntheticBow(const Trajectory& trajectory, const SyntheticParams& appearance,
                     const SyntheticBowParams& params, std::uint64_t seed) {
  return TfIdfFromWords(SyntheticBowWords(trajectory, appearance, params, seed), params.vocabulary);
}

}  // namespace dvpr
