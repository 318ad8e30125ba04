// The page's data, worked out by hand for a tiny run, and the page being self-contained.
#include <string>

#include <gtest/gtest.h>

#include "experiments/replay/replay_page.h"

namespace dvpr::replay {
namespace {

ReplayRun TinyRun() {
  ReplayRun run;
  run.robots = 2;
  run.run = 1;
  run.network_variant = 0;
  run.network = NetworkLabel{.model = "point_to_point", .bandwidth_bps = 1e7, .latency_ms = 2, .loss = "none"};
  StrategyMessages d{"decentralized", {}};
  // sent 1000 ns = 1 us, delivered 2501000 ns = 2501 us: latency 2500 us
  d.messages.push_back({1000, 2501000, 0, 1, MessageRole::kQuery, QueueEffect::kRequest, 587, false});
  // sent 1499 ns rounds to 1 us (0 after the previous send); dropped: -1
  d.messages.push_back({1499, -1, 1, 0, MessageRole::kReply, QueueEffect::kAnswer, 95, true});
  // sent 0.1 s = 100000 us (99999 after the previous); never delivered, not dropped: -2
  d.messages.push_back({100000000, -1, 0, 1, MessageRole::kQuery, QueueEffect::kRequest, 587, false});
  run.strategies.push_back(d);
  return run;
}

Tracks TinyTracks() {
  Tracks t;
  t.name = "tiny";
  t.fps = 10;
  t.robots.push_back({0, {1.04, 2.0}, {-0.25, 3.0}});  // decimetres: 10, -3 (half away from zero), 20, 30
  t.robots.push_back({2, {-7.5}, {0.0}});               // -75, 0
  return t;
}

TEST(ReplayPageTest, DataIsCompactAndWorkedOutByHand) {
  EXPECT_EQ(PageData(TinyRun(), TinyTracks()),
            "{\"name\":\"tiny\",\"robots\":2,\"run\":1,\"variant\":0,"
            "\"network\":\"point-to-point, 10 Mbit/s, 2 ms\",\"fps\":10,"
            "\"roles\":[\"query\",\"reply\",\"verify request\",\"verify result\",\"re-clustering\",\"other\"],"
            "\"first\":[0,2],\"tracks\":[[10,-3,20,30],[-75,0]],"
            "\"strategies\":[{\"name\":\"decentralized\",\"kinds\":[[0,587,1],[1,95,-1]],"
            "\"m\":[1,2500,0,1,0,0,-1,1,0,1,99999,-2,0,1,0]}]}");
}

// On a radio the page gets the range (to draw it) and each message's hops (to draw its relays),
// and the network's name ends with the radio and its routing.
TEST(ReplayPageTest, ARadioAddsItsRangeAndTheHops) {
  ReplayRun run = TinyRun();
  run.network.model = "radio";
  run.network.propagation = "range 150m";
  run.network.range_m = 150;
  run.network.next_hop = "shortest_path";
  run.strategies[0].messages[0].hops = 2;
  run.strategies[0].messages[1].hops = 0;  // dropped before its first transmission
  EXPECT_EQ(PageData(run, TinyTracks()),
            "{\"name\":\"tiny\",\"robots\":2,\"run\":1,\"variant\":0,"
            "\"network\":\"radio, 10 Mbit/s, 2 ms, range 150m shortest_path\",\"fps\":10,\"range_m\":150,"
            "\"roles\":[\"query\",\"reply\",\"verify request\",\"verify result\",\"re-clustering\",\"other\"],"
            "\"first\":[0,2],\"tracks\":[[10,-3,20,30],[-75,0]],"
            "\"strategies\":[{\"name\":\"decentralized\",\"kinds\":[[0,587,1],[1,95,-1]],"
            "\"m\":[1,2500,0,1,0,0,-1,1,0,1,99999,-2,0,1,0],\"h\":[2,0,1]}]}");
}

TEST(ReplayPageTest, NamesCannotCloseTheScriptElement) {
  Tracks t = TinyTracks();
  t.name = "a</script>\"b\\";
  const std::string data = PageData(TinyRun(), t);
  EXPECT_NE(data.find("\"name\":\"a\\u003c/script\\u003e\\\"b\\\\\""), std::string::npos) << data;
}

// Every string of the page's JSON is ASCII: non-ASCII characters as \\uXXXX (U+2028 and U+2029
// are line ends to older JavaScript, so never raw), a character beyond U+FFFF as its UTF-16
// surrogate pair, bytes that are not UTF-8 as U+FFFD; '&', '>' and control characters escaped.
TEST(ReplayPageTest, NamesAreAsciiJsonWhateverTheirBytes) {
  Tracks t = TinyTracks();
  // é, U+2028, U+2029, U+1F600 (F0 9F 98 80 = D83D DE00), a stray FF, a cut E2 82, a newline.
  t.name = "caf\xc3\xa9\xe2\x80\xa8\xe2\x80\xa9\xf0\x9f\x98\x80|\xff|\xe2\x82|&>\n<!--";
  ReplayRun run = TinyRun();
  run.strategies[0].strategy = "it's `x` $(y); \"z\"";
  const std::string data = PageData(run, t);
  EXPECT_NE(data.find("\"name\":\"caf\\u00e9\\u2028\\u2029\\ud83d\\ude00|\\ufffd|\\ufffd\\ufffd|"
                      "\\u0026\\u003e\\u000a\\u003c!--\""),
            std::string::npos) << data;
  EXPECT_NE(data.find("{\"name\":\"it's `x` $(y); \\\"z\\\"\""), std::string::npos) << data;
  for (const char c : data) EXPECT_LT(static_cast<unsigned char>(c), 0x80);
}

// Opened without a network: nothing fetched (no URL, no src=, no import), the data inside.
TEST(ReplayPageTest, SelfContained) {
  const std::string page = ReplayPage(TinyRun(), TinyTracks());
  for (const char* remote : {"http:", "https:", "//cdn", "src=", "import ", "fetch(", "XMLHttpRequest", "@import", "url("}) {
    EXPECT_EQ(page.find(remote), std::string::npos) << remote;
  }
  EXPECT_EQ(page.find(kDataPlaceholder), std::string::npos);
  EXPECT_NE(page.find("<script id=\"replay-data\" type=\"application/json\">{\"name\":\"tiny\""), std::string::npos);
  EXPECT_EQ(page.rfind("</html>\n"), page.size() - 8);
}

}  // namespace
}  // namespace dvpr::replay
