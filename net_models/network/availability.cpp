#include "net_models/network/availability.h"

#include <algorithm>
#include <iterator>
#include <stdexcept>
#include <string>

namespace dvpr {

Availability::Availability(int nodes)
    : nodes_(nodes),
      offline_from_(static_cast<std::size_t>(nodes), SimTime::Max()),
      offline_until_(static_cast<std::size_t>(nodes), SimTime::Max()) {}

void Availability::SetOffline(NodeId node, SimTime from, SimTime until) {
  offline_from_[static_cast<std::size_t>(node.value)] = from;
  offline_until_[static_cast<std::size_t>(node.value)] = until;
}

void Availability::SetTalkWindows(NodeId node, std::vector<TalkWindow> windows) {
  for (std::size_t i = 0; i < windows.size(); ++i) {
    if (!(windows[i].from < windows[i].until) || (i > 0 && windows[i].from < windows[i - 1].until)) {
      throw std::invalid_argument("Network::SetTalkWindows: node " + std::to_string(node.value) + ": window " +
                                  std::to_string(i) + " is empty or not after the one before it");
    }
  }
  if (talk_windows_.empty()) talk_windows_.resize(static_cast<std::size_t>(nodes_));
  talk_windows_[static_cast<std::size_t>(node.value)] = std::move(windows);
}

bool Availability::InTalkWindow(NodeId node, SimTime at) const {
  if (talk_windows_.empty()) return true;
  const std::vector<TalkWindow>& w = talk_windows_[static_cast<std::size_t>(node.value)];
  if (w.empty()) return true;
  // The last window that opens at or before `at`: it is the only one that can hold it.
  const auto it = std::upper_bound(w.begin(), w.end(), at, [](SimTime t, const TalkWindow& x) { return t < x.from; });
  return it != w.begin() && at < std::prev(it)->until;
}

}  // namespace dvpr
