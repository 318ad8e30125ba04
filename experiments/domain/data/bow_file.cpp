#include "experiments/domain/data/bow_file.h"

#include <algorithm>
#include <cctype>
#include <bit>
#include <cstdint>
#include <iterator>
#include <charconv>
#include <cmath>
#include <fstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "experiments/domain/data/printable.h"
#include "experiments/domain/data/text_file.h"

namespace dvpr {
namespace {

namespace fs = std::filesystem;

using text_file::FailLine;

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
  // Weights are float32: one that rounds to 0 there (below about 1.4e-45) would silently be no
  // word at all.
  if (static_cast<float>(weight) == 0.0f) bad("the weight is 0 in float32 (the smallest is about 1.4e-45)");
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

// One 12-byte triple, read little-endian whatever the host's byte order.
struct Triple {
  std::int32_t frame;
  std::int32_t word;
  float weight;
};

std::uint32_t LittleEndian32(const unsigned char* p) {
  return static_cast<std::uint32_t>(p[0]) | static_cast<std::uint32_t>(p[1]) << 8 |
         static_cast<std::uint32_t>(p[2]) << 16 | static_cast<std::uint32_t>(p[3]) << 24;
}

constexpr std::size_t kTripleBytes = 12;

[[noreturn]] void FailTriple(const fs::path& path, std::size_t i, const std::string& what) {
  throw std::runtime_error(path.string() + ": triple " + std::to_string(i) + " (byte " +
                           std::to_string(i * kTripleBytes) + "): " + what);
}

Triple ParseTriple(const fs::path& path, std::size_t i, const unsigned char* p) {
  const auto frame = static_cast<std::int32_t>(LittleEndian32(p));
  const auto word = static_cast<std::int32_t>(LittleEndian32(p + 4));
  const float weight = std::bit_cast<float>(LittleEndian32(p + 8));
  if (frame < 0 || frame >= kMaxBowFrame) {
    FailTriple(path, i, "frame " + std::to_string(frame) + ": expected a whole number in [0, 10000000)");
  }
  if (word < 0 || word >= kMaxBowWord) {
    FailTriple(path, i, "word " + std::to_string(word) + ": expected a whole number in [0, 10000000)");
  }
  if (!std::isfinite(weight) || weight < 0.0f || weight > 1e30f) {
    FailTriple(path, i, "weight " + std::to_string(weight) + ": expected a number in [0, 1e30]");
  }
  return {frame, word, weight};
}

std::vector<unsigned char> ReadBytes(const fs::path& path) {
  if (const std::string why = text_file::ThereButNotARegularFile(path); !why.empty()) text_file::Fail(path, why);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path.string() + ": cannot open for reading");
  std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw std::runtime_error(path.string() + ": read error");
  return bytes;
}

// The triples grouped by frame (in file order within a frame), then each frame sorted by word;
// the record index rides along so that a repeated word names its second triple.
BowData LoadBowTriples(const fs::path& path) {
  const std::vector<unsigned char> bytes = ReadBytes(path);
  if (bytes.empty()) throw std::runtime_error(path.string() + ": file is empty (expected 12-byte triples)");
  if (bytes.size() % kTripleBytes != 0) {
    throw std::runtime_error(path.string() + ": " + std::to_string(bytes.size()) +
                             " bytes is not a whole number of 12-byte (frame, word, weight) triples");
  }
  const std::size_t count = bytes.size() / kTripleBytes;
  std::vector<Triple> triples(count);
  std::int32_t last_frame = 0;
  for (std::size_t i = 0; i < count; ++i) {
    triples[i] = ParseTriple(path, i, bytes.data() + i * kTripleBytes);
    last_frame = std::max(last_frame, triples[i].frame);
  }
  std::vector<std::vector<std::size_t>> by_frame(static_cast<std::size_t>(last_frame) + 1);
  for (std::size_t i = 0; i < count; ++i) by_frame[static_cast<std::size_t>(triples[i].frame)].push_back(i);
  BowData data;
  data.frames.resize(by_frame.size());
  for (std::size_t f = 0; f < by_frame.size(); ++f) {
    std::vector<std::size_t>& ids = by_frame[f];
    std::stable_sort(ids.begin(), ids.end(), [&](std::size_t a, std::size_t b) { return triples[a].word < triples[b].word; });
    for (std::size_t k = 1; k < ids.size(); ++k) {
      if (triples[ids[k]].word == triples[ids[k - 1]].word) {
        FailTriple(path, ids[k], "frame " + std::to_string(f) + ", word " + std::to_string(triples[ids[k]].word) +
                                     " appears twice (first in triple " + std::to_string(ids[k - 1]) + ")");
      }
    }
    BowVector v;
    for (std::size_t i : ids) {
      if (triples[i].weight > 0.0f) v.push_back({triples[i].word, triples[i].weight});
    }
    for (const BowEntry& e : v) data.vocabulary = std::max(data.vocabulary, e.word + 1);
    data.frames[f] = L1Normalised(std::move(v));
  }
  return data;
}

BowData LoadBowText(const fs::path& path) {
  if (const std::string why = text_file::ThereButNotARegularFile(path); !why.empty()) text_file::Fail(path, why);
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path.string() + ": cannot open for reading");
  std::vector<std::string> lines;
  for (std::string text; std::getline(in, text);) lines.push_back(std::move(text));
  if (in.bad()) throw std::runtime_error(path.string() + ": read error");
  if (!lines.empty()) lines.front() = std::string(text_file::WithoutByteOrderMark(lines.front()));
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

}  // namespace

BowData LoadBowFile(const fs::path& path) {
  // .bin in any case: BOW.BIN is the binary triples too (it was read as text).
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  const bool binary = ext == ".bin";
  BowData data = binary ? LoadBowTriples(path) : LoadBowText(path);
  // Without a single word every BoW query finds nothing: a run would report a recall of 0 as if
  // it had measured one.
  if (data.vocabulary == 0) {
    throw std::runtime_error(path.string() + ": no frame has a word (" +
                             (binary ? "every weight is 0" : "every line is '-'") + "; expected at least one WORD:WEIGHT)");
  }
  return data;
}

}  // namespace dvpr
