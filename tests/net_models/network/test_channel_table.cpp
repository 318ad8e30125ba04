// The names of a network's messages (net_models/network/channel_table.h): ids handed out in order and
// given again for the same name, members kept sorted and joined once, and ids another table
// handed out refused by name.
#include "net_models/network/channel_table.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace dvpr {
namespace {

TEST(ChannelTable, AnIdIsGivenOncePerNameInTheOrderNamesCome) {
  ChannelTable t;
  const ChannelId q3 = t.InternChannel("DVPR_QUERY_3");
  const ChannelId all = t.InternChannel("DVPR_BROADCAST");
  EXPECT_EQ(static_cast<std::uint32_t>(q3), 0u);
  EXPECT_EQ(static_cast<std::uint32_t>(all), 1u);
  EXPECT_EQ(t.InternChannel("DVPR_QUERY_3"), q3);
  EXPECT_EQ(t.ChannelName(all), "DVPR_BROADCAST");
  EXPECT_EQ(t.ChannelNameString(q3), "DVPR_QUERY_3");
  const MessageTypeId query = t.InternType("dvpr.query_t");
  EXPECT_EQ(static_cast<std::uint32_t>(query), 0u);  // types count apart from channels
  EXPECT_EQ(t.TypeName(query), "dvpr.query_t");
}

TEST(ChannelTable, MembersAreSortedAndJoinAndLeaveAreIdempotent) {
  ChannelTable t;
  const ChannelId c = t.InternChannel("DVPR_BROADCAST");
  for (const int n : {3, 1, 2, 1, 3}) t.Join(NodeId(n), c);
  EXPECT_EQ(t.At(c).members, (std::vector<NodeId>{NodeId(1), NodeId(2), NodeId(3)}));
  t.Leave(NodeId(2), c);
  t.Leave(NodeId(2), c);
  t.Leave(NodeId(7), c);
  EXPECT_EQ(t.At(c).members, (std::vector<NodeId>{NodeId(1), NodeId(3)}));
  EXPECT_FALSE(t.At(c).link_local);
  t.SetLinkLocal(c);
  EXPECT_TRUE(t.At(c).link_local);
}

TEST(ChannelTable, AnIdItDidNotHandOutIsRefusedByName) {
  ChannelTable t;
  const ChannelId c = t.InternChannel("DVPR_BROADCAST");
  const MessageTypeId m = t.InternType("dvpr.query_t");
  EXPECT_NO_THROW(t.CheckNames(c, m));
  try {
    t.CheckNames(ChannelId{1}, m);
    FAIL() << "channel id 1 was accepted";
  } catch (const std::out_of_range& e) {
    EXPECT_EQ(std::string(e.what()), "Network: channel id 1 was not interned by this network");
  }
  try {
    t.CheckNames(c, MessageTypeId{5});
    FAIL() << "type id 5 was accepted";
  } catch (const std::out_of_range& e) {
    EXPECT_EQ(std::string(e.what()), "Network: message type id 5 was not interned by this network");
  }
  EXPECT_THROW(t.Join(NodeId(0), ChannelId{2}), std::out_of_range);
}

}  // namespace
}  // namespace dvpr
