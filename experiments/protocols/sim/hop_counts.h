#pragma once
// radio.csv's delivered_by_hops: the run's delivered copies counted by the transmissions each
// took (MessageCopy::hops at delivery), for the hop histogram (radio_hops.png). Subscribed on
// radio variants only; the counts sum to Network::Routes().delivered.
#include <cstdint>
#include <vector>

#include "net_models/network/network_observer.h"

namespace dvpr {

class HopCountRecorder : public NetworkObserver {
 public:
  void OnDelivered(const MessageCopy& copy, SimTime) override {
    if (copy.hops < 1) return;  // every delivered copy made a transmission
    const auto h = static_cast<std::size_t>(copy.hops);
    if (by_hops_.size() < h) by_hops_.resize(h, 0);
    ++by_hops_[h - 1];
  }
  // [k]: the copies delivered after k + 1 hops, up to the most any took.
  const std::vector<std::int64_t>& by_hops() const { return by_hops_; }

 private:
  std::vector<std::int64_t> by_hops_;
};

}  // namespace dvpr
