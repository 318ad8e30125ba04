#pragma once
// Users' own bag-of-words vectors (config: dataset.bow; docs/bow.md), a sparse text format:
//
//   one frame per line, in frame order; on each line whitespace-separated WORD:WEIGHT pairs,
//   WORD a whole number in [0, 10000000), WEIGHT a finite number > 0 (already weighted, e.g.
//   tf-idf: dvpr uses the weights as they are and only L1-normalises each frame);
//   a frame with no words is a line holding a single '-'.
//
// A pair may appear in any order; a word twice on one line is an error. The vocabulary is the
// largest word + 1. Errors are std::runtime_error "<file>: line <n>: <problem>".
#include <filesystem>

#include "experiments/data/bow_data.h"

namespace dvpr {

inline constexpr int kMaxBowWord = 10000000;  // words are below this (DBoW2 vocabularies: 10^6)

BowData LoadBowFile(const std::filesystem::path& path);

}  // namespace dvpr
