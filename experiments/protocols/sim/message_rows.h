#pragma once
// messages.csv rows (results.h MessageRow) recorded from a Network's hooks:
// one row per copy of a message, added at its send and completed at its
// delivery or drop, in send order. delivered_ns stays empty for a copy that
// was dropped or still in flight when the run ended; the RunKey is left for
// the caller to stamp.
#include <cstdint>
#include <vector>

#include "experiments/results/results.h"
#include "net_models/network_observer.h"

namespace dvpr {

class MessageRowRecorder : public NetworkObserver {
 public:
  void OnSent(const MessageCopy& copy) override;
  void OnDelivered(const MessageCopy& copy, SimTime at) override;
  void OnDropped(const MessageCopy& copy, SimTime at, DropReason reason) override;

  const std::vector<MessageRow>& rows() const { return rows_; }
  std::vector<MessageRow> TakeRows() { return std::move(rows_); }

 private:
  // The row of a copy sent while subscribed, or null.
  MessageRow* RowOf(const MessageCopy& copy);

  std::uint64_t first_copy_ = 0;  // MessageCopy::copy of rows_[0]
  std::vector<MessageRow> rows_;
};

}  // namespace dvpr
