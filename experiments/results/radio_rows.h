#pragma once
// The rows of radio.csv (docs/network_model.md, "The radio"), written only when a network variant
// of the sweep is `model: radio`: how the run's copies travelled - the hops of the delivered ones,
// what the robots relayed for each other, and why the others were lost. Plain data, as results.h.
#include <array>
#include <cstdint>
#include <vector>

#include "experiments/results/results.h"

namespace dvpr {

// Why a copy was lost, in radio.csv's column order (net_models' DropReason without kNone).
inline constexpr std::array<const char*, 11> kRadioDropReasons = {
    "queue_full", "loss",    "offline",     "no_route",    "out_of_range", "hop_limit",
    "buffer_full", "expired", "stale_route", "retry_limit", "collision"};

// One row of radio.csv: one run of one strategy on a radio variant.
struct RadioRow {
  RunKey key;
  std::int64_t delivered_copies = 0;
  double mean_hops = kNotApplicable;      // over the delivered copies; NaN when none arrived
  std::int64_t max_hops = 0;
  std::int64_t relay_transmissions = 0;   // all robots' transmissions of others' messages
  std::int64_t relay_bytes = 0;           // and their frame bytes
  std::int64_t held_copies = 0;           // copies held for want of a route (store-and-forward), each once
  std::int64_t routing_transmissions = 0; // all robots' routing beacons (link_state), sent and forwarded
  std::int64_t routing_bytes = 0;         // and their frame bytes
  std::array<std::int64_t, kRadioDropReasons.size()> dropped{};  // copies lost, by kRadioDropReasons
  // [k]: the delivered copies that took k + 1 hops, up to max_hops (sums to delivered_copies);
  // radio.csv's last column, the counts separated by spaces.
  std::vector<std::int64_t> delivered_by_hops;
};

}  // namespace dvpr
