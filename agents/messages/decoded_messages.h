#pragma once
// Decoded messages that the handlers of one delivered message share, and may keep.
//
// Why: a broadcast query reaches 99 robots of the 100-robot team. Decoding its 544 bytes once
// instead of 99 times, and letting each robot's queued search point at that one decoded
// descriptor instead of copying it into a task of its own, leaves 100 hot descriptors a frame
// where there were 9900 cold copies. The simulated transports of one network share one
// DecodedMessages (Transport::ShareDecodes) and name each delivery by the network's message
// number, so the 99 deliveries of one publish find it decoded; a transport on its own (LCM)
// names no delivery and decodes each one, into a message its pool reuses once nobody holds it.
//
// MessageRef counts its holders without atomics: a pool and every reference to its messages
// belong to one thread (a simulation, or one LCM agent's handler thread).
#include <cstdint>
#include <memory>
#include <span>
#include <utility>
#include <vector>

#include "agents/messages/lcm_codec.h"

namespace dvpr {

template <class Msg>
class DecodedPool;

namespace decoded_detail {
template <class Msg>
struct Node {
  Msg msg;
  DecodedPool<Msg>* pool = nullptr;
  std::uint32_t refs = 0;
};
}  // namespace decoded_detail

// Keeps one decoded message alive (and unchanged) while any copy of it exists. Empty when the
// bytes did not decode.
template <class Msg>
class MessageRef {
 public:
  MessageRef() = default;
  MessageRef(const MessageRef& o) : node_(o.node_) {
    if (node_ != nullptr) ++node_->refs;
  }
  MessageRef(MessageRef&& o) noexcept : node_(std::exchange(o.node_, nullptr)) {}
  MessageRef& operator=(const MessageRef& o) {
    MessageRef(o).swap(*this);
    return *this;
  }
  MessageRef& operator=(MessageRef&& o) noexcept {
    MessageRef(std::move(o)).swap(*this);
    return *this;
  }
  ~MessageRef() { Reset(); }

  void Reset() {
    if (node_ != nullptr && --node_->refs == 0) node_->pool->Free(node_);
    node_ = nullptr;
  }
  void swap(MessageRef& o) noexcept { std::swap(node_, o.node_); }
  explicit operator bool() const { return node_ != nullptr; }
  const Msg& operator*() const { return node_->msg; }
  const Msg* operator->() const { return &node_->msg; }

 private:
  friend class DecodedPool<Msg>;
  using Node = decoded_detail::Node<Msg>;
  explicit MessageRef(Node* node) : node_(node) { ++node_->refs; }
  Node* node_ = nullptr;
};

// The decoded messages of one type. A message nobody holds is decoded over again for a later
// delivery (DecodeInto keeps its arrays' capacity): no allocation per message once warm.
template <class Msg>
class DecodedPool {
 public:
  DecodedPool() = default;
  DecodedPool(const DecodedPool&) = delete;
  DecodedPool& operator=(const DecodedPool&) = delete;
  ~DecodedPool() { last_ = {}; }  // before the nodes it points into

  // `bytes` decoded; empty if they do not decode as Msg. Delivery `key` != 0 names the message
  // the bytes belong to: the same key as the last call gives that call's message (or its
  // failure) without decoding; key 0 always decodes.
  MessageRef<Msg> Decode(std::uint64_t key, std::span<const std::uint8_t> bytes) {
    if (key != 0 && key == last_key_) return last_;
    Node* node = Take();
    MessageRef<Msg> ref(node);
    const bool ok = DecodeInto(bytes, node->msg);
    if (!ok) ref = {};
    last_ = ref;
    last_key_ = key;
    return ref;
  }

 private:
  friend class MessageRef<Msg>;
  using Node = decoded_detail::Node<Msg>;

  Node* Take() {
    if (free_.empty()) {
      nodes_.push_back(std::make_unique<Node>());
      nodes_.back()->pool = this;
      return nodes_.back().get();
    }
    Node* node = free_.back();
    free_.pop_back();
    return node;
  }
  void Free(Node* node) { free_.push_back(node); }

  std::vector<std::unique_ptr<Node>> nodes_;  // every message ever made; addresses stay put
  std::vector<Node*> free_;                   // held by nobody, last freed first taken (warm)
  MessageRef<Msg> last_;                      // the last call's message (empty: it failed)
  std::uint64_t last_key_ = 0;
};

// One DecodedPool per message type, made on first use. Must outlive every MessageRef taken
// from it (a transport's agents hold them in their queues).
class DecodedMessages {
 public:
  template <class Msg>
  DecodedPool<Msg>& Pool() {
    for (const Entry& e : pools_) {
      if (e.tag == &kTag<Msg>) return *static_cast<DecodedPool<Msg>*>(e.pool.get());
    }
    auto pool = std::make_shared<DecodedPool<Msg>>();
    pools_.push_back(Entry{&kTag<Msg>, pool});
    return *pool;
  }

 private:
  template <class Msg>
  static constexpr char kTag = 0;  // its address names the type
  struct Entry {
    const void* tag;
    std::shared_ptr<void> pool;
  };
  std::vector<Entry> pools_;
};

}  // namespace dvpr
