#include "experiments/domain/data/synthetic.h"

#include "sim/random_bits.h"

#include <charconv>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

namespace dvpr {
namespace {

// Normal sampler with a spare value over the shared xoshiro256**: std::normal_distribution
// differs between standard libraries.
class Rng {
 public:
  explicit Rng(std::uint64_t seed) : gen_(seed) {}
  std::uint64_t Next() { return gen_.Next(); }
  double Uniform() { return gen_.Uniform(); }  // [0, 1)
  double Uniform(double lo, double hi) { return lo + (hi - lo) * Uniform(); }
  double Normal() {  // Box-Muller; the second value of each pair is kept for the next call
    if (has_spare_) {
      has_spare_ = false;
      return spare_;
    }
    const double u1 = 1.0 - Uniform();  // (0, 1]: log stays finite
    const double radius = std::sqrt(-2.0 * std::log(u1));
    const double angle = 2.0 * std::numbers::pi * Uniform();
    spare_ = radius * std::sin(angle);
    has_spare_ = true;
    return radius * std::cos(angle);
  }

 private:
  Xoshiro256 gen_;
  double spare_ = 0.0;
  bool has_spare_ = false;
};

// Independent streams of one seed: adding a stream never changes the others.
enum Stream : std::uint64_t {
  kDeploymentEnvironment = 1,
  kDeploymentFrames = 2,
  kDeploymentLikeFrames = 3,
  kDiverseFrames = 4,
  kDiverseEnvironments = 1000,  // + environment index
};
Rng StreamRng(std::uint64_t seed, std::uint64_t stream) {
  std::uint64_t state = seed;
  std::uint64_t mixed = SplitMix64(state) ^ (stream * 0xD1B54A32D192ED03ULL);
  return Rng(SplitMix64(mixed));
}

constexpr int kTimeFeatures = 32;

// One environment: its mean and the random Fourier features of its place field and of its
// appearance change. Weight matrices are dim x features, row-major.
struct Environment {
  std::vector<double> mean;
  std::vector<double> place_weights, pos_freq, head_freq, place_phase;  // freqs: 2 per feature
  std::vector<double> time_weights, time_freq, time_phase;
};

std::vector<double> Normals(Rng& rng, std::size_t n, double scale) {
  std::vector<double> v(n);
  for (auto& x : v) x = scale * rng.Normal();
  return v;
}

Environment MakeEnvironment(const SyntheticParams& p, Rng& rng) {
  const auto d = static_cast<std::size_t>(p.dim);
  const auto m = static_cast<std::size_t>(p.place_features);
  Environment e;
  e.mean = Normals(rng, d, p.environment_offset);
  e.place_weights = Normals(rng, d * m, 1.0);
  const double log_min = std::log(p.length_scale_min_m), log_max = std::log(p.length_scale_max_m);
  for (std::size_t k = 0; k < m; ++k) {
    // A Gaussian frequency with a length scale drawn per feature: a mixture of smoothness scales.
    const double length = std::exp(rng.Uniform(log_min, log_max));
    e.pos_freq.push_back(rng.Normal() / length);
    e.pos_freq.push_back(rng.Normal() / length);
    // The first heading_fraction of the features also depend on the heading; the rest see only
    // the place (both are drawn, so the fraction does not shift the random stream).
    const double on = static_cast<double>(k) < p.heading_fraction * static_cast<double>(m) ? 1 : 0;
    e.head_freq.push_back(on * rng.Normal() / p.heading_scale);
    e.head_freq.push_back(on * rng.Normal() / p.heading_scale);
    e.place_phase.push_back(rng.Uniform(0.0, 2.0 * std::numbers::pi));
  }
  e.time_weights = Normals(rng, d * kTimeFeatures, p.appearance_change);
  e.time_freq = Normals(rng, kTimeFeatures, 1.0 / p.appearance_time_scale_frames);
  for (int l = 0; l < kTimeFeatures; ++l) e.time_phase.push_back(rng.Uniform(0.0, 2.0 * std::numbers::pi));
  return e;
}

// Where and when a frame is taken: ground-plane position (x, z), unit heading (hx, hz), time.
struct Sample {
  double x, z, hx, hz, t;
};

// Accumulates features times weights into `out` (dim values), in a fixed order so the result
// does not depend on vectorisation.
void AddFeatures(const std::vector<double>& features, const std::vector<double>& weights,
                 std::vector<double>& out) {
  const std::size_t m = features.size();
  for (std::size_t j = 0; j < out.size(); ++j) {
    const double* w = &weights[j * m];
    double sum = 0.0;
    for (std::size_t k = 0; k < m; ++k) sum += w[k] * features[k];
    out[j] += sum;
  }
}

// Renders the frames of one environment into rows [first, first + samples.size()) of `out`.
class Renderer {
 public:
  explicit Renderer(const SyntheticParams& p) : p_(p), decay_(static_cast<std::size_t>(p.dim)) {
    // Standard deviation of dimension j: (j + 1)^(-decay / 2), like a PCA spectrum.
    for (std::size_t j = 0; j < decay_.size(); ++j) {
      decay_[j] = std::pow(static_cast<double>(j + 1), -0.5 * p.variance_decay);
    }
  }

  void Render(const Environment& e, const std::vector<Sample>& samples, Rng& noise,
              DescriptorMatrix& out, Eigen::Index first) const {
    const std::size_t m = e.place_phase.size();
    const double place_norm = std::sqrt(2.0 / static_cast<double>(m));
    const double time_norm = std::sqrt(2.0 / kTimeFeatures);
    std::vector<double> phi(m), psi(kTimeFeatures), x(decay_.size());
    for (std::size_t i = 0; i < samples.size(); ++i) {
      const Sample& s = samples[i];
      for (std::size_t k = 0; k < m; ++k) {
        phi[k] = place_norm * std::cos(e.pos_freq[2 * k] * s.x + e.pos_freq[2 * k + 1] * s.z +
                                       e.head_freq[2 * k] * s.hx + e.head_freq[2 * k + 1] * s.hz +
                                       e.place_phase[k]);
      }
      for (std::size_t l = 0; l < psi.size(); ++l) {
        psi[l] = time_norm * std::cos(e.time_freq[l] * s.t + e.time_phase[l]);
      }
      x = e.mean;
      AddFeatures(phi, e.place_weights, x);
      AddFeatures(psi, e.time_weights, x);
      double norm2 = 0.0;
      for (std::size_t j = 0; j < x.size(); ++j) {
        x[j] = decay_[j] * (x[j] + p_.noise * noise.Normal());
        norm2 += x[j] * x[j];
      }
      const double inv = 1.0 / std::sqrt(norm2);
      const Eigen::Index row = first + static_cast<Eigen::Index>(i);
      for (std::size_t j = 0; j < x.size(); ++j) {
        out(row, static_cast<Eigen::Index>(j)) = static_cast<float>(x[j] * inv);
      }
    }
  }

 private:
  const SyntheticParams& p_;
  std::vector<double> decay_;
};

// `count` random places in the square [origin, origin + area)^2, headings and times uniform.
std::vector<Sample> RandomSamples(int count, double origin, double area, Rng& rng) {
  std::vector<Sample> samples(static_cast<std::size_t>(count));
  for (auto& s : samples) {
    s.x = origin + rng.Uniform(0.0, area);
    s.z = origin + rng.Uniform(0.0, area);
    const double angle = rng.Uniform(0.0, 2.0 * std::numbers::pi);
    s.hx = std::cos(angle);
    s.hz = std::sin(angle);
    // Far apart in time, so every sample sees its own appearance-change draw.
    s.t = rng.Uniform(0.0, 1e9);
  }
  return samples;
}

// Deployment-like training places lie this far from the deployment's, in another area.
constexpr double kOtherAreaOrigin_m = 1e5;

// The shortest text that reads back to `v` (as the config's range errors print values).
std::string Shortest(double v) {
  char buf[32];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  return ec == std::errc() ? std::string(buf, end) : std::string("?");
}

void Require(bool ok, const char* field, const std::string& why) {
  if (!ok) throw std::invalid_argument(std::string(field) + ": " + why);
}

}  // namespace

void SyntheticParams::Validate() const {
  Require(dim > 0, "dim", "must be positive, got " + std::to_string(dim));
  Require(place_features > 0, "place_features", "must be positive");
  Require(length_scale_min_m > 0 && std::isfinite(length_scale_min_m), "length_scale_min_m",
          "must be positive");
  Require(length_scale_max_m >= length_scale_min_m && std::isfinite(length_scale_max_m),
          "length_scale_max_m", "must be finite and at least length_scale_min_m");
  Require(heading_scale > 0 && std::isfinite(heading_scale), "heading_scale", "must be positive");
  Require(heading_fraction >= 0 && heading_fraction <= 1, "heading_fraction", "must lie in [0, 1]");
  Require(variance_decay >= 0 && std::isfinite(variance_decay), "variance_decay", "must not be negative");
  // The three scales are relative to the field's unit std; up to kMaxRelativeScale a frame's
  // values and their squares stay far inside float before the row is normalised (1e30 made them
  // inf, and the descriptors NaN).
  const auto scale = [](const char* field, double v) {
    Require(v >= 0 && v <= SyntheticParams::kMaxRelativeScale, field,
            "must be in [0, 1000000], got " + Shortest(v));
  };
  scale("noise", noise);
  scale("appearance_change", appearance_change);
  Require(appearance_time_scale_frames > 0 && std::isfinite(appearance_time_scale_frames),
          "appearance_time_scale_frames", "must be positive");
  scale("environment_offset", environment_offset);
}

void SyntheticTrainingParams::Validate() const {
  Require(samples >= 0, "samples", "must not be negative, got " + std::to_string(samples));
  Require(environments >= 1, "environments", "must be at least 1");
  Require(training_area_m > 0 && std::isfinite(training_area_m), "training_area_m", "must be positive");
}

DescriptorMatrix SyntheticDeployment(const Trajectory& trajectory, const SyntheticParams& params,
                                     std::uint64_t seed) {
  std::vector<double> times(static_cast<std::size_t>(trajectory.size()));
  for (std::size_t i = 0; i < times.size(); ++i) times[i] = static_cast<double>(i);
  return SyntheticDeployment(trajectory, times, params, seed);
}

DescriptorMatrix SyntheticDeployment(const Trajectory& trajectory, std::span<const double> time_frames,
                                     const SyntheticParams& params, std::uint64_t seed) {
  params.Validate();
  if (time_frames.size() != static_cast<std::size_t>(trajectory.size())) {
    throw std::invalid_argument("synthetic deployment: " + std::to_string(time_frames.size()) + " times for " +
                                std::to_string(trajectory.size()) + " poses");
  }
  Rng env_rng = StreamRng(seed, kDeploymentEnvironment);
  const Environment env = MakeEnvironment(params, env_rng);
  std::vector<Sample> samples(static_cast<std::size_t>(trajectory.size()));
  for (Eigen::Index i = 0; i < trajectory.size(); ++i) {
    // KITTI's ground plane is x-z; the heading is projected onto it.
    const double hx = trajectory.headings(i, 0), hz = trajectory.headings(i, 2);
    const double hn = std::hypot(hx, hz);
    samples[static_cast<std::size_t>(i)] = {trajectory.positions(i, 0), trajectory.positions(i, 2),
                                            hn > 0 ? hx / hn : 0.0, hn > 0 ? hz / hn : 0.0,
                                            time_frames[static_cast<std::size_t>(i)]};
  }
  DescriptorMatrix out(trajectory.size(), params.dim);
  Rng noise = StreamRng(seed, kDeploymentFrames);
  Renderer(params).Render(env, samples, noise, out, 0);
  return out;
}

DescriptorMatrix SyntheticTrainingDiverse(const SyntheticParams& params,
                                          const SyntheticTrainingParams& training, std::uint64_t seed) {
  params.Validate();
  training.Validate();
  const int count = training.samples;
  DescriptorMatrix out(count, params.dim);
  Rng frames = StreamRng(seed, kDiverseFrames);
  const Renderer renderer(params);
  Eigen::Index first = 0;
  for (int e = 0; e < training.environments; ++e) {
    // Rows are grouped by environment; the first count % environments get one frame more.
    const int share = count / training.environments + (e < count % training.environments ? 1 : 0);
    Rng env_rng = StreamRng(seed, kDiverseEnvironments + static_cast<std::uint64_t>(e));
    const Environment env = MakeEnvironment(params, env_rng);
    renderer.Render(env, RandomSamples(share, 0.0, training.training_area_m, frames), frames, out,
                    first);
    first += share;
  }
  return out;
}

DescriptorMatrix SyntheticTrainingDeploymentLike(const SyntheticParams& params,
                                                 const SyntheticTrainingParams& training,
                                                 std::uint64_t seed) {
  params.Validate();
  training.Validate();
  Rng env_rng = StreamRng(seed, kDeploymentEnvironment);
  const Environment env = MakeEnvironment(params, env_rng);
  Rng frames = StreamRng(seed, kDeploymentLikeFrames);
  DescriptorMatrix out(training.samples, params.dim);
  Renderer(params).Render(
      env, RandomSamples(training.samples, kOtherAreaOrigin_m, training.training_area_m, frames), frames, out, 0);
  return out;
}

}  // namespace dvpr
