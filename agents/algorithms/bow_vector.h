#pragma once
// Bag-of-words vectors and DBoW2's L1 score (docs/bow.md). A frame's local features are
// quantised to visual words; its vector holds one tf-idf weight per word it contains (Sivic and
// Zisserman 2003; Nister and Stewenius 2006), L1-normalised, so every score lies in [0, 1]:
//
//   tf(w)  = features of the frame quantised to w / features of the frame
//   idf(w) = ln(N / N_w), N documents, N_w of them contain w (InverseDocumentFrequency)
//   v(w)   = tf(w) idf(w) / sum_u tf(u) idf(u)
//   s(v, w) = 1 - 0.5 |v/|v|_1 - w/|w|_1|_1     (DBoW2's L1 score, Galvez-Lopez and Tardos 2012)
//
// For non-negative vectors of L1 norm 1, |a - b|_1 = 2 - 2 sum_w min(a_w, b_w), so
// s = sum over the words both contain of min(a_w, b_w): only shared words count, which is what
// makes an inverted index (and its split over robots) work.
#include <cstdint>
#include <span>
#include <vector>

namespace dvpr {

struct BowEntry {
  std::int32_t word = 0;
  float weight = 0.0f;
  bool operator==(const BowEntry&) const = default;
};

// Sorted by word, each word once, weights > 0.
using BowVector = std::vector<BowEntry>;

// One frame's words (one per local feature, repeats allowed) as a term-frequency vector
// (counts / feature count), sorted by word.
BowVector TermFrequencies(std::span<const std::int32_t> feature_words);

// idf(w) = ln(N / N_w) over `documents` (term-frequency or weighted vectors; only which words
// they contain counts); 0 for a word no document contains. One value per word of the vocabulary.
std::vector<double> InverseDocumentFrequency(std::span<const BowVector> documents, int vocabulary);

// tf x idf, words whose weight is 0 (in every document) dropped, then L1-normalised. A vector
// whose words all have idf 0 comes back empty.
BowVector WeightTfIdf(const BowVector& tf, std::span<const double> idf);

// Divides by the L1 norm (an empty or all-zero vector stays as it is).
BowVector L1Normalised(BowVector v);

// DBoW2's L1 score of the two vectors, each normalised first; 0 when either is empty.
double L1Score(const BowVector& a, const BowVector& b);

// sum over shared words of min(a_w, b_w): the L1 score of vectors already L1-normalised, and
// the share of it a subset of the words contributes (a robot's partial score).
double SharedMinimum(const BowVector& a, const BowVector& b);

}  // namespace dvpr
