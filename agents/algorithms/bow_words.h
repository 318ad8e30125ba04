#pragma once
// The distributed inverted index (Cieslewski and Scaramuzza, ICRA 2017; docs/bow.md): the words
// of the vocabulary are assigned to the robots before deployment, a query's vector is split so
// each robot receives the coefficients of its own words, each robot answers with the frame its
// part matches best, and the querying robot takes the frame returned most consistently.
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "agents/algorithms/bow_vector.h"
#include "agents/algorithms/ids.h"

namespace dvpr {

// Which robot owns each word of the vocabulary.
class WordOwners {
 public:
  // Word w to robot w mod n (the ICRA 2017 paper's assignment).
  static WordOwners Modulo(int vocabulary, int robots);
  // Load-aware: words by document frequency (descending; ties by word id) each to the robot
  // with the least document frequency so far (ties: lowest id), Graham's LPT. A word's
  // document frequency is the number of partial queries and stored entries it causes, so this
  // evens out what each robot receives and stores.
  static WordOwners ByDocumentFrequency(std::span<const std::int64_t> document_frequency, int robots);
  // Every word to `server`: a team's centralized index (bow_centralized in a simulated or real
  // team, docs/bow.md), where one robot scores and keeps every frame's whole vector.
  static WordOwners Server(int vocabulary, int robots, RobotId server);

  int robots() const { return robots_; }
  int vocabulary() const { return static_cast<int>(owner_.size()); }
  RobotId OwnerOf(std::int32_t word) const { return RobotId(owner_[static_cast<std::size_t>(word)]); }
  // The vector's entries per robot (robots() parts, each sorted by word; empty where the robot
  // owns none of its words). Weights are kept as they are (normalised over the whole vector).
  std::vector<BowVector> Split(const BowVector& v) const;

 private:
  WordOwners(std::vector<std::int16_t> owner, int robots) : owner_(std::move(owner)), robots_(robots) {}
  std::vector<std::int16_t> owner_;
  int robots_ = 0;
};

// Number of documents containing each word (InverseDocumentFrequency's N_w).
std::vector<std::int64_t> DocumentFrequency(std::span<const BowVector> documents, int vocabulary);

// One robot's answer to its partial query: the stored frame its part scores best, and that
// partial score (the sum over its words of min(query, stored) weights).
struct PartialMatch {
  RobotId responder;
  RobotId match_robot;  // the robot that observed the frame
  FrameId frame;
  double score = 0.0;
};

struct VotedMatch {
  RobotId match_robot;
  FrameId frame;
  int votes = 0;
  double score = 0.0;  // the voters' partial scores summed: the share of the full L1 score they saw
};

// Step 4: the frame returned by the most robots; ties go to the larger summed score, then the
// lower frame id. Empty when no robot returned a frame.
std::optional<VotedMatch> Vote(std::span<const PartialMatch> answers);

}  // namespace dvpr
