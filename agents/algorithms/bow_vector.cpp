#include "agents/algorithms/bow_vector.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace dvpr {

BowVector TermFrequencies(std::span<const std::int32_t> feature_words) {
  std::vector<std::int32_t> words(feature_words.begin(), feature_words.end());
  std::sort(words.begin(), words.end());
  BowVector tf;
  const double total = static_cast<double>(words.size());
  for (std::size_t i = 0; i < words.size();) {
    std::size_t j = i;
    while (j < words.size() && words[j] == words[i]) ++j;
    tf.push_back({words[i], static_cast<float>(static_cast<double>(j - i) / total)});
    i = j;
  }
  return tf;
}

std::vector<double> InverseDocumentFrequency(std::span<const BowVector> documents, int vocabulary) {
  std::vector<std::int64_t> containing(static_cast<std::size_t>(vocabulary), 0);
  for (const BowVector& d : documents) {
    for (const BowEntry& e : d) {
      if (e.word < 0 || e.word >= vocabulary) {
        throw std::out_of_range("word " + std::to_string(e.word) + " outside the vocabulary of " +
                                std::to_string(vocabulary));
      }
      ++containing[static_cast<std::size_t>(e.word)];
    }
  }
  std::vector<double> idf(containing.size(), 0.0);
  const double n = static_cast<double>(documents.size());
  for (std::size_t w = 0; w < idf.size(); ++w) {
    if (containing[w] > 0) idf[w] = std::log(n / static_cast<double>(containing[w]));
  }
  return idf;
}

BowVector WeightTfIdf(const BowVector& tf, std::span<const double> idf) {
  BowVector v;
  v.reserve(tf.size());
  for (const BowEntry& e : tf) {
    const double w = static_cast<double>(e.weight) * idf[static_cast<std::size_t>(e.word)];
    if (w > 0.0) v.push_back({e.word, static_cast<float>(w)});
  }
  return L1Normalised(std::move(v));
}

BowVector L1Normalised(BowVector v) {
  double norm = 0.0;
  for (const BowEntry& e : v) norm += std::abs(static_cast<double>(e.weight));
  if (norm == 0.0) return v;
  for (BowEntry& e : v) e.weight = static_cast<float>(static_cast<double>(e.weight) / norm);
  return v;
}

double SharedMinimum(const BowVector& a, const BowVector& b) {
  double s = 0.0;
  auto i = a.begin(), j = b.begin();
  while (i != a.end() && j != b.end()) {
    if (i->word < j->word) {
      ++i;
    } else if (j->word < i->word) {
      ++j;
    } else {
      s += std::min(static_cast<double>(i->weight), static_cast<double>(j->weight));
      ++i, ++j;
    }
  }
  return s;
}

double L1Score(const BowVector& a, const BowVector& b) {
  if (a.empty() || b.empty()) return 0.0;
  // The formula itself, over the union of the words (SharedMinimum is its shortcut).
  const BowVector x = L1Normalised(a), y = L1Normalised(b);
  double distance = 0.0;
  auto i = x.begin(), j = y.begin();
  while (i != x.end() || j != y.end()) {
    if (j == y.end() || (i != x.end() && i->word < j->word)) {
      distance += std::abs(static_cast<double>(i++->weight));
    } else if (i == x.end() || j->word < i->word) {
      distance += std::abs(static_cast<double>(j++->weight));
    } else {
      distance += std::abs(static_cast<double>(i++->weight) - static_cast<double>(j++->weight));
    }
  }
  return 1.0 - 0.5 * distance;
}

}  // namespace dvpr
