#pragma once
// The bag-of-words view of the synthetic world (docs/bow.md): local features whose visual words
// follow the place a frame sees, for the BoW strategies (Cieslewski and Scaramuzza, ICRA 2017).
//
// Landmarks are scattered over the ground plane (landmark_density per square metre, drawn per
// 10 m cell from the seed, so the world is unbounded and the same wherever it is looked at),
// each with one visual word drawn uniformly from the vocabulary. A frame at (x, z) with heading h
// sees the landmarks within range_m and within field_of_view_deg / 2 of h, and draws `features`
// local features from them, each landmark in proportion to
//   exp(-distance / range_m) x exp(appearance_change x sqrt(2) cos(omega_l t + phi_l)),
// omega_l ~ N(0, 1 / appearance_time_scale_frames^2): a landmark's visibility drifts over time
// with the global descriptors' appearance_change and time scale (light, parked cars). A share
// noise / (1 + noise) of the features are quantisation noise, a word drawn uniformly from the
// vocabulary (noise is the global descriptors' dataset.synthetic.noise). A revisit from nearby in
// the same direction draws from the same landmarks, so shares words; other places mostly do not.
// Deterministic for a seed: landmark cells and frames each have their own stream.
#include <cstdint>
#include <vector>

#include "agents/algorithms/bow_vector.h"
#include "experiments/data/bow_data.h"
#include "experiments/data/dataset.h"
#include "experiments/data/synthetic.h"

namespace dvpr {

// config: dataset.synthetic_bow. Validate() throws std::invalid_argument "<field>: <problem>".
struct SyntheticBowParams {
  int features = 500;               // local features per frame, [1, 100000]
  int vocabulary = 100000;          // visual words, [2, 10000000]
  double landmark_density = 0.2;    // landmarks per square metre, (0, 10]
  double range_m = 40.0;            // farthest landmark a frame sees, (0, 1000]
  double field_of_view_deg = 90.0;  // (0, 360]
  void Validate() const;
  bool operator==(const SyntheticBowParams&) const = default;
};

// The words of every frame's features along `trajectory` (frame index = time), one vector of
// `features` words per frame. `appearance` gives noise, appearance_change and its time scale.
std::vector<std::vector<std::int32_t>> SyntheticBowWords(const Trajectory& trajectory,
                                                         const SyntheticParams& appearance,
                                                         const SyntheticBowParams& params, std::uint64_t seed);

// Every frame's tf-idf vector (bow_vector.h), idf over these frames themselves (docs/bow.md).
BowData TfIdfFromWords(const std::vector<std::vector<std::int32_t>>& words, int vocabulary);

// SyntheticBowWords then TfIdfFromWords.
BowData SyntheticBow(const Trajectory& trajectory, const SyntheticParams& appearance,
                     const SyntheticBowParams& params, std::uint64_t seed);

}  // namespace dvpr
