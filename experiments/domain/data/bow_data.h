#pragma once
// The bag-of-words vectors of a deployment's frames (docs/bow.md), beside its descriptors:
// synthetic (synthetic_bow.h) or the user's file (bow_file.h). Read only when a bow_ strategy runs.
#include <vector>

#include "agents/algorithms/bow_vector.h"

namespace dvpr {

// tf-idf weighted (or the user's weights), L1-normalised, one vector per frame.
struct BowData {
  int vocabulary = 0;             // words are below this
  std::vector<BowVector> frames;
  bool empty() const { return frames.empty(); }
};

}  // namespace dvpr
