#pragma once
// The rows of bow.csv and bow_sizes.csv (docs/bow.md), written only when a bow_ strategy runs:
// what the distributed inverted index sent and how its vote did, and the same query traffic of
// the descriptor strategies beside them. Plain data, as results.h.
#include <cstdint>

#include "experiments/results/results.h"

namespace dvpr {

// One row of bow.csv: one run of one strategy.
struct BowRow {
  RunKey key;
  std::int64_t queries = 0;
  std::int64_t partial_queries = 0;         // query messages sent to other robots
  std::int64_t payload_bytes = 0;           // their LCM-encoded bytes
  double mean_words = kNotApplicable;       // words per query vector (bow_ strategies)
  double mean_part_words = kNotApplicable;  // words per message sent (bow_ strategies)
  std::int64_t part_bytes_p50 = 0;          // message sizes: median, 90th percentile, largest
  std::int64_t part_bytes_p90 = 0;
  std::int64_t part_bytes_max = 0;
  std::int64_t voted = 0;                   // queries that got a frame back (bow_ strategies)
  std::int64_t vote_not_centralized = 0;    // of which another frame than the centralized BoW best
};

// One row of bow_sizes.csv: how many query messages of one run had this encoded size.
struct BowSizeRow {
  RunKey key;
  std::int64_t payload_bytes = 0;
  std::int64_t messages = 0;
};

}  // namespace dvpr
