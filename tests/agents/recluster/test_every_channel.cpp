// Every channel of every message type, in one place. Each LCM type of lcmtypes/dvpr/*.lcm travels
// on at least one channel; every channel the agents publish on (agents/messages/channels.h,
// agents/messages/team_sync.h, agents/recluster/recluster_messages.h; the routing daemon's,
// net_models/link_state/daemon/link_state_daemon.h) is one of the message catalogue's (lcmtypes/channels/channels.h),
// with the LCM type it carries and the role that the simulation's recorders, the LCM agent
// process and `dvpr replay` all read from the catalogue. The names, types and roles below are
// written by hand from the protocol (docs/design.md section 1, docs/bow.md).
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "agents/messages/channels.h"
#include "agents/recluster/recluster_messages.h"
#include "agents/messages/team_sync.h"
#include "lcmtypes/channels/channels.h"

namespace dvpr {
namespace {

using channels::ChannelKind;

struct Published {
  std::string channel;  // as the agent names it
  const char* name;     // the name it must have, by hand
  ChannelKind kind;
  const char* lcm_type;
  MessageRole role;
};

std::vector<Published> EveryPublishedChannel() {
  return {
      {channels::Query(RobotId(3)), "DVPR_QUERY_3", ChannelKind::kQuery, "query_t", MessageRole::kQuery},
      {channels::Probe(RobotId(12)), "DVPR_PROBE_12", ChannelKind::kProbe, "query_t", MessageRole::kQuery},
      {channels::Store(RobotId(0)), "DVPR_STORE_0", ChannelKind::kStore, "query_t", MessageRole::kQuery},
      {channels::kQueryAll, "DVPR_QUERY_ALL", ChannelKind::kQueryAll, "query_t", MessageRole::kQuery},
      {channels::Match(RobotId(1)), "DVPR_MATCH_1", ChannelKind::kMatch, "match_t", MessageRole::kReply},
      {channels::VerifyRequest(RobotId(4)), "DVPR_VREQ_4", ChannelKind::kVerifyRequest, "verify_request_t",
       MessageRole::kVerifyRequest},
      {channels::VerifyResult(RobotId(19)), "DVPR_VRES_19", ChannelKind::kVerifyResult, "verify_result_t",
       MessageRole::kVerifyResult},
      {channels::BowQuery(RobotId(7)), "DVPR_BOWQ_7", ChannelKind::kBowQuery, "bow_query_t", MessageRole::kQuery},
      {channels::BowProbe(RobotId(0)), "DVPR_BOWP_0", ChannelKind::kBowProbe, "bow_query_t", MessageRole::kQuery},
      {channels::BowMatch(RobotId(11)), "DVPR_BOWM_11", ChannelKind::kBowMatch, "bow_match_t", MessageRole::kReply},
      {channels::Sample(RobotId(0)), "DVPR_SAMPLE_0", ChannelKind::kSample, "descriptor_batch_t",
       MessageRole::kRecluster},
      {channels::Migrate(RobotId(5)), "DVPR_MIGRATE_5", ChannelKind::kMigrate, "descriptor_batch_t",
       MessageRole::kRecluster},
      {channels::kTable, "DVPR_TABLE", ChannelKind::kTable, "centroid_table_t", MessageRole::kRecluster},
      // Heartbeats are the team's upkeep, counted as "other" in the result files.
      {channels::kStatus, "DVPR_STATUS", ChannelKind::kStatus, "agent_status_t", MessageRole::kOther},
      // link_state routing's beacons are the network's upkeep: "other" too.
      {channels::kHello, "DVPR_HELLO", ChannelKind::kHello, "routing_hello_t", MessageRole::kOther},
      {channels::kTopology, "DVPR_TOPOLOGY", ChannelKind::kTopology, "routing_topology_t", MessageRole::kOther},
  };
}

TEST(EveryChannel, EachPublishedChannelIsTheCataloguesWithItsTypeAndRole) {
  std::set<ChannelKind> kinds;
  for (const Published& p : EveryPublishedChannel()) {
    EXPECT_EQ(p.channel, p.name);
    const auto kind = channels::KindOf(p.channel);
    ASSERT_TRUE(kind.has_value()) << p.channel;
    EXPECT_EQ(*kind, p.kind) << p.channel;
    EXPECT_EQ(channels::LcmTypeOf(*kind), p.lcm_type) << p.channel;
    EXPECT_EQ(channels::RoleOf(p.channel), p.role) << p.channel;
    kinds.insert(*kind);
  }
  // The agents publish on every channel of the catalogue: none is left unnamed above.
  EXPECT_EQ(static_cast<int>(kinds.size()), channels::kChannelKinds);
  EXPECT_EQ(static_cast<int>(channels::AllChannels().size()), channels::kChannelKinds);
}

TEST(EveryChannel, EachLcmTypeTravelsOnAChannelAndEachChannelsTypeExists) {
  std::set<std::string> lcm_files;
  for (const auto& e : std::filesystem::directory_iterator(std::filesystem::path(DVPR_SOURCE_DIR) / "lcmtypes/dvpr")) {
    if (e.path().extension() == ".lcm") lcm_files.insert(e.path().stem().string());
  }
  ASSERT_FALSE(lcm_files.empty());
  std::set<std::string> carried;
  for (const Published& p : EveryPublishedChannel()) carried.insert(p.lcm_type);
  for (const channels::ChannelSpec& spec : channels::AllChannels()) {
    EXPECT_TRUE(lcm_files.contains(std::string(channels::LcmTypeOf(spec.kind)))) << spec.name;
  }
  EXPECT_EQ(carried, lcm_files);
}

}  // namespace
}  // namespace dvpr
