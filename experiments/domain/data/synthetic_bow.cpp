#include "experiments/domain/data/synthetic_bow.h"

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

// Whether a cell holds no landmark `v` can see, decided from the cell's square alone: it lies
// wholly beyond range_m, or (field of view below 180 degrees) wholly behind the camera. Only a
// shortcut: every landmark of such a cell fails Visible's own test by far more than rounding, so
// the words are the same with or without it (and a cell's landmarks are its own draws, however
// many cells are looked at).
bool OutOfSight(std::int64_t cx, std::int64_t cz, const View& v, double range_m, double cos_half) {
  constexpr double kMargin = 1e-6;  // metres; rounding is ~1e-13 here
  const double x0 = static_cast<double>(cx) * kCell_m, z0 = static_cast<double>(cz) * kCell_m;
  const double x1 = x0 + kCell_m, z1 = z0 + kCell_m;
  const double gx = std::max({x0 - v.x, 0.0, v.x - x1}), gz = std::max({z0 - v.z, 0.0, v.z - z1});
  if (std::sqrt(gx * gx + gz * gz) > range_m + kMargin) return true;
  if (cos_half <= 0) return false;
  const auto ahead = [&](double x, double z) { return (x - v.x) * v.hx + (z - v.z) * v.hz; };
  return std::max({ahead(x0, z0), ahead(x0, z1), ahead(x1, z0), ahead(x1, z1)}) < -kMargin;
}

// A landmark in view and where it lies from the camera. Its word (which needs the viewing
// direction: an atan2, and a draw when sectors are on) is worked out only when a feature is
// drawn from it: a frame sees about 5000 landmarks and draws a few hundred features from them.
struct Seen {
  const Landmark* landmark;  // in LandmarkField's cells, which stay where they are
  double dx, dz;
};

// The landmarks `v` sees and their cumulative draw weights.
void Visible(LandmarkField& field, const View& v, const SyntheticBowParams& p, const SyntheticParams& a,
             std::vector<Seen>& seen, std::vector<double>& cumulative) {
  seen.clear();
  cumulative.clear();
  const double cos_half = std::cos(p.field_of_view_deg * std::numbers::pi / 360.0);
  const auto lo = [&](double c) { return static_cast<std::int64_t>(std::floor((c - p.range_m) / kCell_m)); };
  const auto hi = [&](double c) { return static_cast<std::int64_t>(std::floor((c + p.range_m) / kCell_m)); };
  // Shortcuts before the exact test below, each far from its boundary: a landmark whose squared
  // distance exceeds range^2 (1 + 1e-9) is beyond range_m however hypot rounds; one behind the
  // camera (a negative dot product) is outside a field of view below 180 degrees.
  const double far_squared = p.range_m * p.range_m * (1.0 + 1e-9);
  double total = 0.0;
  for (std::int64_t cx = lo(v.x); cx <= hi(v.x); ++cx) {
    for (std::int64_t cz = lo(v.z); cz <= hi(v.z); ++cz) {
      if (OutOfSight(cx, cz, v, p.range_m, cos_half)) continue;
      for (const Landmark& l : field.Cell(cx, cz)) {
        const double dx = l.x - v.x, dz = l.z - v.z;
        if (dx * dx + dz * dz > far_squared) continue;
        const double ahead = dx * v.hx + dz * v.hz;
        if (cos_half > 0 && ahead < 0) continue;  // d > 0 here: d = 0 gives ahead = 0
        const double d = std::hypot(dx, dz);
        if (d > p.range_m || (d > 0 && ahead / d < cos_half)) continue;
        const double drift = a.appearance_change * std::numbers::sqrt2 * std::cos(l.omega * v.t + l.phase);
        total += std::exp(-d / p.range_m + drift);
        seen.push_back({&l, dx, dz});
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

void RequireBowParam(bool ok, const char* field, const std::string& why) {
  if (!ok) throw std::invalid_argument(std::string(field) + ": " + why);
}

}  // namespace

void SyntheticBowParams::Validate() const {
  RequireBowParam(features >= 1 && features <= 100000, "features", "must be in [1, 100000], got " + std::to_string(features));
  RequireBowParam(vocabulary >= 2 && vocabulary <= 10000000, "vocabulary",
          "must be in [2, 10000000], got " + std::to_string(vocabulary));
  RequireBowParam(landmark_density > 0 && landmark_density <= 10, "landmark_density", "must be in (0, 10]");
  RequireBowParam(range_m > 0 && range_m <= 1000, "range_m", "must be in (0, 1000]");
  RequireBowParam(field_of_view_deg > 0 && field_of_view_deg <= 360, "field_of_view_deg", "must be in (0, 360]");
  RequireBowParam(common_words >= 0 && common_words < vocabulary, "common_words",
          "must be in [0, vocabulary - 1 = " + std::to_string(vocabulary - 1) + "], got " + std::to_string(common_words));
  RequireBowParam(common_share >= 0 && common_share <= 1, "common_share", "must be in [0, 1]");
  RequireBowParam(common_share == 0 || common_words >= 1, "common_share", "needs common_words >= 1 when above 0");
  RequireBowParam(view_sector_deg > 0 && view_sector_deg <= 360, "view_sector_deg", "must be in (0, 360]");
}

std::vector<std::vector<std::int32_t>> SyntheticBowWords(const Trajectory& trajectory,
                                                         const SyntheticParams& appearance,
                                                         const SyntheticBowParams& params, std::uint64_t seed,
                                                         const FrameProgress& progress) {
  params.Validate();
  appearance.Validate();
  LandmarkField field(params, appearance, seed);
  const double noise_share = appearance.noise / (1.0 + appearance.noise);
  const auto vocabulary = static_cast<std::uint64_t>(params.vocabulary);
  const auto common = static_cast<std::uint64_t>(params.common_words);
  const bool aliasing = params.common_share > 0;
  std::vector<std::vector<std::int32_t>> out(static_cast<std::size_t>(trajectory.size()));
  std::vector<Seen> seen;
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
      const Seen& l = seen[static_cast<std::size_t>(std::min<std::ptrdiff_t>(at, std::ssize(seen) - 1))];
      words.push_back(field.WordSeenFrom(*l.landmark, std::atan2(-l.dz, -l.dx)));
    }
    if (progress) progress(static_cast<std::size_t>(i) + 1, out.size());
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
                     const SyntheticBowParams& params, std::uint64_t seed, const FrameProgress& progress) {
  return TfIdfFromWords(SyntheticBowWords(trajectory, appearance, params, seed, progress), params.vocabulary);
}

}  // namespace dvpr
