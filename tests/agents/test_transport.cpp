// Transport's typed subscriptions (agents/messages/transport.h), on a loopback transport written here that
// calls the handlers from inside Publish: the hardest case for the message each subscription
// decodes into and reuses.
#include "agents/messages/transport.h"

#include <gtest/gtest.h>

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace dvpr {
namespace {

class LoopbackTransport final : public Transport {
 public:
  SimTime Now() const override { return SimTime::Zero(); }
  std::int64_t UtimeAt(SimTime t) const override { return t.us(); }
  void ScheduleAfter(SimTime, Callback fn) override { fn(); }
  void Inject(const std::string& channel, const std::vector<std::uint8_t>& bytes) { Deliver(channel, bytes); }
  // A delivery named `key`, as a transport that shares its decoded messages names them.
  void InjectAs(std::uint64_t key, const std::string& channel, const std::vector<std::uint8_t>& bytes) {
    delivery_key_ = key;
    Deliver(channel, bytes);
    delivery_key_ = 0;
  }

 private:
  void DoPublish(const std::string& channel, const char*, std::vector<std::uint8_t> bytes) override {
    Deliver(channel, bytes);
  }
  std::uint64_t DoSubscribe(const std::string& channel, RawHandler handler) override {
    handlers_.emplace(next_id_, std::pair(channel, std::move(handler)));
    return next_id_++;
  }
  void DoUnsubscribe(std::uint64_t id) override { handlers_.erase(id); }
  void Deliver(const std::string& channel, const std::vector<std::uint8_t>& bytes) {
    for (const auto& [id, entry] : handlers_) {
      if (entry.first == channel) entry.second(channel, bytes);
    }
  }
  std::map<std::uint64_t, std::pair<std::string, RawHandler>> handlers_;
  std::uint64_t next_id_ = 1;
};

query_t Query(std::int32_t frame, std::vector<float> descriptor) {
  query_t q{};
  q.frame = frame;
  q.dim = static_cast<std::int16_t>(descriptor.size());
  q.descriptor = std::move(descriptor);
  return q;
}

TEST(TransportSubscribe, EachMessageIsDecodedWholeIntoTheReusedOne) {
  LoopbackTransport t;
  std::vector<std::pair<std::int32_t, std::vector<float>>> seen;
  const Subscription sub = t.Subscribe<query_t>("Q", [&](const query_t& q) { seen.emplace_back(q.frame, q.descriptor); });
  t.Publish("Q", Query(1, {1.0f, 2.0f, 3.0f}));
  t.Publish("Q", Query(2, {}));  // the generated decoder leaves an empty array alone
  t.Publish("Q", Query(3, {4.0f}));
  using Seen = std::vector<std::pair<std::int32_t, std::vector<float>>>;
  EXPECT_EQ(seen, (Seen{{1, {1.0f, 2.0f, 3.0f}}, {2, {}}, {3, {4.0f}}}));
}

TEST(TransportSubscribe, AHandlerThatPublishesToItselfSeesBothMessagesIntact) {
  LoopbackTransport t;
  std::vector<std::string> log;
  Subscription sub;
  sub = t.Subscribe<query_t>("Q", [&](const query_t& q) {
    log.push_back("in " + std::to_string(q.frame) + " " + std::to_string(q.descriptor.size()));
    if (q.frame == 1) t.Publish("Q", Query(2, {7.0f}));  // delivered from inside this call
    log.push_back("out " + std::to_string(q.frame) + " " + std::to_string(q.descriptor.size()));
  });
  t.Publish("Q", Query(1, {1.0f, 2.0f}));
  EXPECT_EQ(log, (std::vector<std::string>{"in 1 2", "in 2 1", "out 2 1", "out 1 2"}));
  t.Publish("Q", Query(3, {}));  // after the nested call, the reused message is free again
  EXPECT_EQ(log.back(), "out 3 0");
}

TEST(TransportIntern, TheSameNameGivesTheSameChannelAndPublishesUnderItsName) {
  LoopbackTransport t;
  const PublishChannel a = t.Intern("A");
  const PublishChannel b = t.Intern("B");
  EXPECT_NE(a, b);
  EXPECT_EQ(t.Intern("A"), a);
  EXPECT_EQ(static_cast<std::uint32_t>(a), 0u);  // numbered from 0 in the order first interned
  EXPECT_EQ(static_cast<std::uint32_t>(b), 1u);
  EXPECT_EQ(t.NameOf(b), "B");
  std::vector<std::string> seen;
  const Subscription sub_a = t.Subscribe<query_t>("A", [&](const query_t& q) { seen.push_back("A" + std::to_string(q.frame)); });
  const Subscription sub_b = t.Subscribe<query_t>("B", [&](const query_t& q) { seen.push_back("B" + std::to_string(q.frame)); });
  const std::size_t interned_bytes = t.Publish(b, Query(1, {1.0f}));
  EXPECT_EQ(interned_bytes, t.Publish("B", Query(2, {2.0f})));
  t.Publish(a, Query(3, {}));
  EXPECT_EQ(seen, (std::vector<std::string>{"B1", "B2", "A3"}));
}

TEST(TransportSubscribe, ABufferThatIsNotTheTypeIsCountedAndDropped) {
  LoopbackTransport t;
  int calls = 0;
  const Subscription sub = t.Subscribe<match_t>("M", [&](const match_t&) { ++calls; });
  t.Inject("M", Encode(Query(1, {1.0f})));
  t.Inject("M", {1, 2, 3});
  EXPECT_EQ(calls, 0);
  EXPECT_EQ(t.MalformedCount(), 2u);
  match_t m{};
  t.Publish("M", m);
  EXPECT_EQ(calls, 1);
}

// Two transports sharing one DecodedMessages, as a simulation's robots do: the deliveries of one
// message (one key) see one decoded message, a new key is decoded anew.
TEST(TransportShareDecodes, DeliveriesOfOneMessageShareOneDecodedMessage) {
  DecodedMessages shared;
  LoopbackTransport a;
  LoopbackTransport b;
  a.ShareDecodes(&shared);
  b.ShareDecodes(&shared);
  std::vector<const query_t*> seen;
  std::vector<std::int32_t> frames;
  const auto handler = [&](const query_t& q) { seen.push_back(&q), frames.push_back(q.frame); };
  const Subscription sub_a = a.Subscribe<query_t>("Q", handler);
  const Subscription sub_b = b.Subscribe<query_t>("Q", handler);
  const auto first = Encode(Query(1, {1.0f}));
  a.InjectAs(7, "Q", first);
  b.InjectAs(7, "Q", first);
  b.InjectAs(8, "Q", Encode(Query(2, {2.0f})));
  ASSERT_EQ(seen.size(), 3u);
  EXPECT_EQ(seen[0], seen[1]);
  EXPECT_EQ(frames, (std::vector<std::int32_t>{1, 1, 2}));
}

// What a kept reference holds stays as it was while later messages are decoded (each into a
// message of its own), and a message nobody holds any more is decoded over again, not a new one.
TEST(TransportShareDecodes, AKeptMessageStaysIntactAndAFreedOneIsReused) {
  LoopbackTransport t;
  std::vector<MessageRef<query_t>> kept;
  std::vector<const query_t*> addresses;
  const Subscription sub = t.SubscribeShared<query_t>("Q", [&](const MessageRef<query_t>& q) {
    kept.push_back(q);
    addresses.push_back(&*q);
  });
  t.Publish("Q", Query(1, {1.0f, 2.0f}));
  t.Publish("Q", Query(2, {3.0f}));
  t.Publish("Q", Query(3, {}));
  ASSERT_EQ(kept.size(), 3u);
  EXPECT_EQ(kept[0]->frame, 1);
  EXPECT_EQ(kept[0]->descriptor, (std::vector<float>{1.0f, 2.0f}));
  EXPECT_EQ(kept[1]->descriptor, (std::vector<float>{3.0f}));
  EXPECT_TRUE(kept[2]->descriptor.empty());
  EXPECT_NE(addresses[0], addresses[1]);
  EXPECT_NE(addresses[1], addresses[2]);
  kept.clear();  // the transport's pool still holds the last one (key 0: never reused as is)
  t.Publish("Q", Query(4, {4.0f}));
  ASSERT_EQ(kept.size(), 1u);
  EXPECT_EQ(kept[0]->frame, 4);
  EXPECT_EQ(kept[0]->descriptor, (std::vector<float>{4.0f}));
  EXPECT_TRUE(&*kept[0] == addresses[0] || &*kept[0] == addresses[1]);  // a freed one, decoded over
}

// A buffer that does not decode fails once per delivery even when its key is shared: each
// transport counts it.
TEST(TransportShareDecodes, AMalformedSharedMessageIsCountedByEveryReceiver) {
  DecodedMessages shared;
  LoopbackTransport a;
  LoopbackTransport b;
  a.ShareDecodes(&shared);
  b.ShareDecodes(&shared);
  int calls = 0;
  const Subscription sub_a = a.Subscribe<match_t>("M", [&](const match_t&) { ++calls; });
  const Subscription sub_b = b.Subscribe<match_t>("M", [&](const match_t&) { ++calls; });
  const std::vector<std::uint8_t> garbage{1, 2, 3};
  a.InjectAs(5, "M", garbage);
  b.InjectAs(5, "M", garbage);
  EXPECT_EQ(calls, 0);
  EXPECT_EQ(a.MalformedCount(), 1u);
  EXPECT_EQ(b.MalformedCount(), 1u);
}

}  // namespace
}  // namespace dvpr
