#include "agents/algorithms/bow_words.h"

#include <algorithm>
#include <map>
#include <numeric>
#include <stdexcept>
#include <string>

namespace dvpr {

namespace {
void CheckRobots(int robots) {
  if (robots < 1 || robots > 32767) {
    throw std::invalid_argument("robots: must be in [1, 32767], got " + std::to_string(robots));
  }
}
}  // namespace

WordOwners WordOwners::Modulo(int vocabulary, int robots) {
  CheckRobots(robots);
  std::vector<std::int16_t> owner(static_cast<std::size_t>(vocabulary));
  for (int w = 0; w < vocabulary; ++w) owner[static_cast<std::size_t>(w)] = static_cast<std::int16_t>(w % robots);
  return WordOwners(std::move(owner), robots);
}

WordOwners WordOwners::Server(int vocabulary, int robots, RobotId server) {
  CheckRobots(robots);
  if (server.value < 0 || server.value >= robots) {
    throw std::invalid_argument("server: robot " + std::to_string(server.value) + " is not in a team of " +
                                std::to_string(robots));
  }
  return WordOwners(std::vector<std::int16_t>(static_cast<std::size_t>(vocabulary),
                                              static_cast<std::int16_t>(server.value)),
                    robots);
}

WordOwners WordOwners::ByDocumentFrequency(std::span<const std::int64_t> document_frequency, int robots) {
  CheckRobots(robots);
  std::vector<std::int32_t> order(document_frequency.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::int32_t a, std::int32_t b) {
    return document_frequency[static_cast<std::size_t>(a)] > document_frequency[static_cast<std::size_t>(b)];
  });
  // (load, robot) of every robot; the least loaded first, lowest id on ties.
  std::vector<std::pair<std::int64_t, int>> heap;
  for (int r = 0; r < robots; ++r) heap.emplace_back(0, r);
  const auto later = [](const auto& a, const auto& b) { return a > b; };
  std::make_heap(heap.begin(), heap.end(), later);
  std::vector<std::int16_t> owner(document_frequency.size());
  for (std::int32_t w : order) {
    std::pop_heap(heap.begin(), heap.end(), later);
    owner[static_cast<std::size_t>(w)] = static_cast<std::int16_t>(heap.back().second);
    heap.back().first += document_frequency[static_cast<std::size_t>(w)];
    std::push_heap(heap.begin(), heap.end(), later);
  }
  return WordOwners(std::move(owner), robots);
}

std::vector<BowVector> WordOwners::Split(const BowVector& v) const {
  std::vector<BowVector> parts(static_cast<std::size_t>(robots_));
  for (const BowEntry& e : v) parts[static_cast<std::size_t>(OwnerOf(e.word).value)].push_back(e);
  return parts;
}

std::vector<std::int64_t> DocumentFrequency(std::span<const BowVector> documents, int vocabulary) {
  std::vector<std::int64_t> df(static_cast<std::size_t>(vocabulary), 0);
  for (const BowVector& d : documents) {
    for (const BowEntry& e : d) ++df[static_cast<std::size_t>(e.word)];
  }
  return df;
}

std::optional<VotedMatch> Vote(std::span<const PartialMatch> answers) {
  std::map<FrameId, VotedMatch> tally;  // ordered by frame id: the last tie-break
  for (const PartialMatch& a : answers) {
    VotedMatch& t = tally[a.frame];
    t.frame = a.frame;
    t.match_robot = a.match_robot;
    ++t.votes;
    t.score += a.score;
  }
  std::optional<VotedMatch> best;
  for (const auto& [frame, t] : tally) {
    if (!best || t.votes > best->votes || (t.votes == best->votes && t.score > best->score)) best = t;
  }
  return best;
}

}  // namespace dvpr
