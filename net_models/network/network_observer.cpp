#include "net_models/network/network_observer.h"

#include <algorithm>
#include <utility>

namespace dvpr {

ObserverSubscription::ObserverSubscription(ObserverSubscription&& other) noexcept
    : list_(std::exchange(other.list_, nullptr)), observer_(std::exchange(other.observer_, nullptr)) {}

ObserverSubscription& ObserverSubscription::operator=(ObserverSubscription&& other) noexcept {
  if (this != &other) {
    Reset();
    list_ = std::exchange(other.list_, nullptr);
    observer_ = std::exchange(other.observer_, nullptr);
  }
  return *this;
}

void ObserverSubscription::Reset() {
  if (list_ != nullptr) list_->Remove(observer_);
  list_ = nullptr;
  observer_ = nullptr;
}

void ObserverList::Remove(NetworkObserver* observer) {
  const auto it = std::find(observers_.begin(), observers_.end(), observer);
  if (it != observers_.end()) observers_.erase(it);
}

}  // namespace dvpr
