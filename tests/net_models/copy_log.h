#pragma once
// A NetworkObserver that writes what happens to each copy as a line ("0>2 delivered at 9376000ns",
// "0>1 at 0ns: no_route"), in the order it happens, and whose transmission each medium use was:
// the network tests compare these with hand-worked lists.
#include <string>
#include <vector>

#include "net_models/network/network_observer.h"

namespace dvpr::testing_support {

class CopyLog : public NetworkObserver {
 public:
  void OnDropped(const MessageCopy& c, SimTime at, DropReason reason) override {
    lines.push_back(std::to_string(c.src.value) + ">" + std::to_string(c.dst.value) + " at " +
                    std::to_string(at.ns()) + "ns: " + std::string(ToString(reason)));
  }
  void OnDelivered(const MessageCopy& c, SimTime at) override {
    lines.push_back(std::to_string(c.src.value) + ">" + std::to_string(c.dst.value) + " delivered at " +
                    std::to_string(at.ns()) + "ns");
    delivered_hops.push_back(c.hops);
  }
  void OnMedium(const MediumReport& m) override { senders.push_back(m.src.value); }

  std::vector<std::string> lines;
  std::vector<int> senders;  // whose transmission each medium use was, in order
  std::vector<int> delivered_hops;  // MessageCopy::hops of each delivered copy, in order
};

}  // namespace dvpr::testing_support
