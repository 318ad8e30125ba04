#pragma once
// messages.csv rows (results.h MessageRow) recorded from a Network's hooks:
// one row per copy of a message sent while subscribed, in send order,
// completed at its delivery or drop. delivered_ns stays empty for a copy that
// was dropped or still in flight when the run ended; the RunKey is left for
// the caller to stamp.
//
// The hot path keeps a small fixed-size record per copy (channel and type as
// the network's ids); the rows, with their strings, are made once, by Rows().
#include <cstdint>
#include <string>
#include <vector>

#include "experiments/results/results.h"
#include "net_models/network/network_observer.h"

namespace dvpr {

class MessageRowRecorder : public NetworkObserver {
 public:
  void OnSent(const MessageCopy& copy) override;
  void OnDelivered(const MessageCopy& copy, SimTime at) override;
  void OnDropped(const MessageCopy& copy, SimTime at, DropReason reason) override;

  std::size_t size() const { return records_.size(); }
  std::vector<MessageRow> Rows() const;

 private:
  struct Record {
    std::int64_t sent_ns = 0;
    std::int64_t delivered_ns = -1;  // -1: not delivered
    std::int64_t payload_bytes = 0;
    std::int64_t wire_bytes = 0;
    NodeId src;
    NodeId dst;
    ChannelId channel{};
    MessageTypeId type{};
    int hops = 0;
    bool dropped = false;
  };
  // The record of a copy sent while subscribed, or null.
  Record* RecordOf(const MessageCopy& copy);
  // Keeps names[id] = name; the network interns names, so an id's name never changes.
  static void Remember(std::vector<std::string>& names, std::uint32_t id, std::string_view name) {
    if (id >= names.size() || names[id].empty()) Learn(names, id, name);
  }
  static void Learn(std::vector<std::string>& names, std::uint32_t id, std::string_view name);

  std::uint64_t first_copy_ = 0;  // MessageCopy::copy of records_[0]
  std::vector<Record> records_;
  std::vector<std::string> channel_names_;  // by ChannelId
  std::vector<std::string> type_names_;     // by MessageTypeId
};

}  // namespace dvpr
