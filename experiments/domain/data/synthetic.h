#pragma once
// The synthetic appearance model (docs/design.md §8, docs/synthetic_model.md): NetVLAD-like
// descriptors for a trajectory when no real features are available, and the two training sets of
// the paper's experiment (diverse: many environments; deployment-like: the deployment's own
// environment).
//
// A descriptor is, before L2 normalisation,
//   decay ⊙ (environment mean + place field(x, z, heading) + appearance change(time) + noise),
// where the place field and the appearance change are sums of random Fourier features, so
// descriptors vary smoothly with position and heading, and decay gives the first dimensions most
// of the variance, as a PCA layer does. Deterministic for a seed, byte-identical across standard
// libraries (own PRNG and normal sampler; only libm's cos/log/sqrt are used).
#include <cstdint>
#include <span>

#include "agents/algorithms/descriptors.h"
#include "experiments/domain/data/dataset.h"

namespace dvpr {

// The appearance model (config: dataset.synthetic; dim is dataset.dim). Validate() throws
// std::invalid_argument "<field>: <problem>" naming the field.
struct SyntheticParams {
  int dim = 128;                         // d: descriptor length
  int place_features = 256;              // random Fourier features of the place field
  double length_scale_min_m = 2.0;       // place field length scales, log-uniform in [min, max]
  double length_scale_max_m = 25.0;
  double heading_scale = 0.7;            // kernel width on the unit heading vector (opposite = 2)
  double heading_fraction = 0.5;         // share of the place features that depend on heading
  double variance_decay = 1.0;           // variance of dimension j ∝ (j + 1)^-variance_decay
  double noise = 0.25;                   // per-frame i.i.d. noise, relative to the field's std
  double appearance_change = 0.45;       // slowly time-varying term (light, traffic), same units
  double appearance_time_scale_frames = 200.0;  // its correlation time, in frames
  double environment_offset = 0.8;       // std of an environment's mean, same units
  // noise, appearance_change and environment_offset lie in [0, kMaxRelativeScale] (Validate).
  static constexpr double kMaxRelativeScale = 1e6;
  void Validate() const;
  bool operator==(const SyntheticParams&) const = default;
};

// The training sets drawn from the model (config: training.synthetic).
struct SyntheticTrainingParams {
  int samples = 20000;                   // training descriptors generated
  int environments = 30;                 // environments in the diverse training set
  double training_area_m = 2000.0;       // side of the square training places are drawn from
  void Validate() const;                 // as SyntheticParams::Validate
  bool operator==(const SyntheticTrainingParams&) const = default;
};

// Descriptors along `trajectory` (frame index = time) in the deployment environment of `seed`.
DescriptorMatrix SyntheticDeployment(const Trajectory& trajectory, const SyntheticParams& params,
                                     std::uint64_t seed);
// The same with each pose's time given, in frame periods on the team's common clock (a planned
// team: two robots at one place at one time see the same light). Frame index i as its time gives
// the overload above, byte for byte.
DescriptorMatrix SyntheticDeployment(const Trajectory& trajectory, std::span<const double> time_frames,
                                     const SyntheticParams& params, std::uint64_t seed);

// training.samples descriptors from training.environments environments, none of them the
// deployment's, at random places, headings and times, spread evenly over the environments.
DescriptorMatrix SyntheticTrainingDiverse(const SyntheticParams& params,
                                          const SyntheticTrainingParams& training, std::uint64_t seed);

// training.samples descriptors from the deployment environment of `seed` (pass the deployment's
// seed) at random places in another area, random headings and times: the same statistics as the
// deployment, other places.
DescriptorMatrix SyntheticTrainingDeploymentLike(const SyntheticParams& params,
                                                 const SyntheticTrainingParams& training,
                                                 std::uint64_t seed);

}  // namespace dvpr
