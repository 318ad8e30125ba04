// The message catalogue's own rules: how a name is made and read back, which names are unicast,
// and the prefix lengths the wire bytes rely on. Expected names written by hand. Every channel
// the agents publish, with its type and role: tests/agents/recluster/test_every_channel.cpp.
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "lcmtypes/channels/channels.h"

namespace dvpr::channels {
namespace {

TEST(ChannelCatalogue, UnicastNamesCarryTheRobotTeamNamesDoNot) {
  EXPECT_EQ(ChannelName(ChannelKind::kQuery, 0), "DVPR_QUERY_0");
  EXPECT_EQ(ChannelName(ChannelKind::kVerifyResult, 123), "DVPR_VRES_123");
  EXPECT_EQ(ChannelName(ChannelKind::kQueryAll), "DVPR_QUERY_ALL");
  EXPECT_EQ(ChannelName(ChannelKind::kTable), "DVPR_TABLE");
  EXPECT_THROW(ChannelName(ChannelKind::kMatch), std::invalid_argument);      // needs a robot
  EXPECT_THROW(ChannelName(ChannelKind::kStatus, 2), std::invalid_argument);  // the team's
}

TEST(ChannelCatalogue, KindOfReadsWholeNamesBeforePrefixes) {
  // DVPR_QUERY_ALL starts with the query prefix but is the broadcast channel.
  EXPECT_EQ(KindOf("DVPR_QUERY_ALL"), ChannelKind::kQueryAll);
  EXPECT_EQ(KindOf("DVPR_QUERY_7"), ChannelKind::kQuery);
  // A unicast channel is read by its prefix alone.
  EXPECT_EQ(KindOf("DVPR_MATCH_x"), ChannelKind::kMatch);
  EXPECT_EQ(KindOf("DVPR_TABLE"), ChannelKind::kTable);
  EXPECT_EQ(KindOf("DVPR_TABLEX"), std::nullopt);  // a team name is matched whole
  EXPECT_EQ(KindOf("DVPR_HEARTBEAT"), std::nullopt);
  EXPECT_EQ(KindOf(""), std::nullopt);
  EXPECT_EQ(RoleOf("DVPR_HEARTBEAT"), MessageRole::kOther);
  EXPECT_EQ(RoleOf("DVPR_SAMPLE_2"), MessageRole::kRecluster);
}

TEST(ChannelCatalogue, EveryNameReadsBackAsItsKind) {
  for (const ChannelSpec& spec : AllChannels()) {
    const std::string name = spec.unicast ? ChannelName(spec.kind, 42) : ChannelName(spec.kind);
    EXPECT_EQ(KindOf(name), spec.kind) << name;
    EXPECT_EQ(RoleOf(name), spec.role) << name;
    EXPECT_FALSE(spec.request && spec.answer) << name;
  }
}

TEST(ChannelCatalogue, NoUnicastPrefixStartsAnother) {
  // Otherwise a channel could be read as two kinds.
  for (const ChannelSpec& a : AllChannels()) {
    for (const ChannelSpec& b : AllChannels()) {
      if (a.kind != b.kind && a.unicast && b.unicast) {
        EXPECT_FALSE(b.name.starts_with(a.name)) << a.name << " " << b.name;
      }
    }
  }
}

TEST(ChannelCatalogue, QueryPrefixesOfOneFamilyHaveOneLength) {
  // The channel name is in the wire bytes: a query costs the same whatever its role.
  EXPECT_EQ(SpecOf(ChannelKind::kQuery).name.size(), 11u);  // "DVPR_QUERY_"
  EXPECT_EQ(SpecOf(ChannelKind::kProbe).name.size(), 11u);
  EXPECT_EQ(SpecOf(ChannelKind::kStore).name.size(), 11u);
  EXPECT_EQ(SpecOf(ChannelKind::kBowQuery).name.size(), 10u);  // "DVPR_BOWQ_"
  EXPECT_EQ(SpecOf(ChannelKind::kBowProbe).name.size(), 10u);
}

}  // namespace
}  // namespace dvpr::channels
