#include "experiments/data/bow_file.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "experiments/data/printable.h"

namespace dvpr {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void FailLine(const fs::path& path, std::size_t line, const std::string& what) {
  throw std::runtime_error(path.string() + ": line " + std::to_string(line) + ": " + what);
}

bool IsSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

// One WORD:WEIGHT token.
BowEntry ParsePair(const fs::path& path, std::size_t line, std::string_view token) {
  const std::size_t colon = token.find(':');
  const auto bad = [&](const std::string& why) {
    FailLine(path, line, "'" + Printable(token, 40) + "': " + why);
  };
  if (colon == std::string_view::npos) bad("expected WORD:WEIGHT");
  const std::string_view word_text = token.substr(0, colon), weight_text = token.substr(colon + 1);
  long long word = -1;
  const auto [wend, wec] = std::from_chars(word_text.data(), word_text.data() + word_text.size(), word);
  if (word_text.empty() || wec != std::errc() || wend != word_text.data() + word_text.size() || word < 0 ||
      word >= kMaxBowWord) {
    bad("the word must be a whole number in [0, 10000000)");
  }
  double weight = 0.0;
  const auto [vend, vec] = std::from_chars(weight_text.data(), weight_text.data() + weight_text.size(), weight);
  if (weight_text.empty() || vec != std::errc() || vend != weight_text.data() + weight_text.size() ||
      !std::isfinite(weight) || weight <= 0.0 || weight > 1e30) {
    bad("the weight must be a number in (0, 1e30]");
  }
  return {static_cast<std::int32_t>(word), static_cast<float>(weight)};
}

BowVector ParseLine(const fs::path& path, std::size_t line, std::string_view text) {
  BowVector v;
  std::size_t i = 0;
  std::vector<std::string_view> tokens;
  while (i < text.size()) {
    while (i < text.size() && IsSpace(text[i])) ++i;
    const std::size_t start = i;
    while (i < text.size() && !IsSpace(text[i])) ++i;
    if (i > start) tokens.push_back(text.substr(start, i - start));
  }
  if (tokens.empty()) FailLine(path, line, "empty line (a frame without words is a single '-')");
  if (tokens.size() == 1 && tokens[0] == "-") return v;
  for (std::string_view t : tokens) v.push_back(ParsePair(path, line, t));
  std::sort(v.begin(), v.end(), [](const BowEntry& a, const BowEntry& b) { return a.word < b.word; });
  for (std::size_t k = 1; k < v.size(); ++k) {
    if (v[k].word == v[k - 1].word) FailLine(path, line, "word " + std::to_string(v[k].word) + " appears twice");
  }
  return L1Normalised(std::move(v));
}

}  // namespace

BowData LoadBowFile(const fs::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path.string() + ": cannot open for reading");
  std::vector<std::string> lines;
  for (std::string text; std::getline(in, text);) lines.push_back(std::move(text));
  if (in.bad()) throw std::runtime_error(path.string() + ": read error");
  // Trailing blank lines end the file (as in the other loaders); a blank line before is an error.
  const auto blank = [](const std::string& s) { return std::all_of(s.begin(), s.end(), IsSpace); };
  while (!lines.empty() && blank(lines.back())) lines.pop_back();
  BowData data;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    data.frames.push_back(ParseLine(path, i + 1, lines[i]));
    for (const BowEntry& e : data.frames.back()) data.vocabulary = std::max(data.vocabulary, e.word + 1);
  }
  if (data.frames.empty()) throw std::runtime_error(path.string() + ": file is empty (expected one frame per line)");
  return data;
}

}  // namespace dvpr
