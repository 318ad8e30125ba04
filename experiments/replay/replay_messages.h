#pragma once
// The messages of one simulated run, read from a result folder's messages.csv
// (docs/design.md section 6) for `dvpr replay`. Columns are found by their header
// names, so columns added later (anywhere) are ignored.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "experiments/replay/message_role.h"
#include "experiments/results/results.h"

namespace dvpr::replay {

// Which run of the folder to replay. An unset field takes the value of the
// first sim row of messages.csv that matches the set ones.
struct Selection {
  std::optional<int> robots;
  std::optional<int> run;
  std::optional<int> network;            // network_variant
  std::vector<std::string> strategies;   // empty: decentralized and broadcast when the run has
                                         // both, else every strategy of the run (file order)
};

struct Message {
  std::int64_t sent_ns = 0;
  std::int64_t delivered_ns = -1;  // -1: dropped, or still in flight when the run ended
  int src = 0;
  int dst = 0;
  MessageRole role = MessageRole::kOther;
  QueueEffect queue = QueueEffect::kNone;
  // The bytes this copy added to what was sent: its wire bytes, except where one transmission
  // reaches every receiver (shared_medium, csma, wifi, a radio without relays): there only a
  // broadcast's first copy counts, as runs.csv's wire_bytes counts it.
  std::int64_t counted_bytes = 0;
  bool dropped = false;
  // Transmissions it took (messages.csv `hops`, written with a radio; else 1): 0 to 1 without
  // relays, up to Network::kMaxHops (64) with them; at least 1 when delivered.
  int hops = 1;
};

struct StrategyMessages {
  std::string strategy;
  std::vector<Message> messages;  // in send order, as messages.csv lists them
};

struct ReplayRun {
  int robots = 0;
  int run = 0;
  int network_variant = 0;
  // The variant's label, from the folder's config (its range to draw, its next hop: whether
  // copies were relayed); messages.csv's network columns are checked against it.
  NetworkLabel network;
  std::vector<StrategyMessages> strategies;  // in the order of Selection::strategies
};

// Reads `messages_csv` and keeps the rows of the selected run (protocol sim); `networks` are the
// labels of the folder's network variants (VariantLabels of its config.yaml). Throws
// std::runtime_error, one line naming the file, when it is missing, malformed, has no sim
// messages, or none of the selection (listing what it has); and naming the line and column, for
// a row of the selected run whose robot is outside the team, whose hops no network can give, or
// whose network is not the config's variant.
ReplayRun ReadReplayRun(const std::filesystem::path& messages_csv, const Selection& selection,
                        std::span<const NetworkLabel> networks);

}  // namespace dvpr::replay
