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
//
// Two weaknesses of local features against a learned global descriptor, both off by default
// (today's world) and set from published numbers in experiments/configs/bow_comparison.yaml:
//  - perceptual aliasing: a share common_share of the non-noise features are repeated structure
//    (road markings, foliage, facades), a word drawn uniformly from the first common_words words
//    of the vocabulary, the same set at every place; landmarks draw their words from the rest;
//  - viewpoint sensitivity: a landmark looks alike only from within a sector of view_sector_deg
//    of viewing directions (each landmark's sectors start at its own random angle); from another
//    sector it quantises to another word. Two views whose viewing directions differ by at least
//    view_sector_deg never share its word, so with view_sector_deg <= 180 - field_of_view_deg a
//    revisit from the opposite heading shares no landmark word.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "agents/algorithms/bow_vector.h"
#include "experiments/domain/data/bow_data.h"
#include "experiments/domain/data/dataset.h"
#include "experiments/domain/data/synthetic.h"

namespace dvpr {

// config: dataset.synthetic_bow. Validate() throws std::invalid_argument "<field>: <problem>".
struct SyntheticBowParams {
  int features = 500;               // local features per frame, [1, 100000]
  int vocabulary = 100000;          // visual words, [2, 10000000]
  double landmark_density = 0.2;    // landmarks per square metre, (0, 10]
  double range_m = 40.0;            // farthest landmark a frame sees, (0, 1000]
  double field_of_view_deg = 90.0;  // (0, 360]
  int common_words = 0;             // words of repeated structure, [0, vocabulary - 1]
  double common_share = 0.0;        // share of non-noise features on them, [0, 1] (needs common_words >= 1)
  double view_sector_deg = 360.0;   // viewing directions one landmark word covers, (0, 360]
  void Validate() const;
  bool operator==(const SyntheticBowParams&) const = default;
};

// Called after each frame with (frames done, frames in all): the world at its largest parameters
// takes about 1.7 s a frame (hours for KITTI 00), so `dvpr run` shows its progress.
using FrameProgress = std::function<void(std::size_t done, std::size_t total)>;

// The words of every frame's features along `trajectory` (frame index = time), one vector of
// `features` words per frame. `appearance` gives noise, appearance_change and its time scale.
std::vector<std::vector<std::int32_t>> SyntheticBowWords(const Trajectory& trajectory,
                                                         const SyntheticParams& appearance,
                                                         const SyntheticBowParams& params, std::uint64_t seed,
                                                         const FrameProgress& progress = {});

// Every frame's tf-idf vector (bow_vector.h), idf over these frames themselves (docs/bow.md).
BowData TfIdfFromWords(const std::vector<std::vector<std::int32_t>>& words, int vocabulary);

// SyntheticBowWords then TfIdfFromWords.
BowData SyntheticBow(const Trajectory& trajectory, const SyntheticParams& appearance,
                     const SyntheticBowParams& params, std::uint64_t seed, const FrameProgress& progress = {});

}  // namespace dvpr
