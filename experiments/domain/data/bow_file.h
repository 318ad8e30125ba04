#pragma once
// Users' own bag-of-words vectors (config: dataset.bow; docs/bow.md), a sparse text format:
//
//   one frame per line, in frame order; on each line whitespace-separated WORD:WEIGHT pairs,
//   WORD a whole number in [0, 10000000), WEIGHT a finite number > 0 (already weighted, e.g.
//   tf-idf: dvpr uses the weights as they are and only L1-normalises each frame);
//   a frame with no words is a line holding a single '-'.
//
// A pair may appear in any order; a word twice on one line is an error. The vocabulary is the
// largest word + 1. A weight that is 0 in float32 (below about 1.4e-45), and a file in which no
// frame has a word (either format), are errors. Errors are std::runtime_error
// "<file>: line <n>: <problem>" (or "<file>: <problem>" for the whole file).
//
// A file whose name ends in .bin holds (frame, word, weight) triples instead, 12 bytes each,
// little-endian: int32 frame in [0, 10000000), int32 word in [0, 10000000), float32 weight,
// finite, in [0, 1e30]. Triples may come in any order; the frames are 0 .. largest frame. A
// weight of 0 adds no word: it only makes its frame exist (a trailing frame without words).
// A (frame, word) twice is an error. Errors are "<file>: triple <i> (byte <offset>): <problem>".
#include <filesystem>

#include "experiments/domain/data/bow_data.h"

namespace dvpr {

inline constexpr int kMaxBowWord = 10000000;   // words are below this (DBoW2 vocabularies: 10^6)
inline constexpr int kMaxBowFrame = 10000000;  // binary triples' frames are below this

// The text format, or the binary triples when the name ends in .bin.
BowData LoadBowFile(const std::filesystem::path& path);

}  // namespace dvpr
