// A message's role (the message catalogue's, lcmtypes/channels/channels.h) and its effect on the
// receiver's queue, for every channel of the protocols, listed here by hand.
#include <string>

#include <gtest/gtest.h>

#include "experiments/replay/message_role.h"

namespace dvpr::replay {
namespace {

struct Case {
  const char* channel;
  MessageRole role;
  QueueEffect queue;
  const char* name;
};

TEST(MessageRoleTest, EveryChannelOfTheProtocols) {
  const Case cases[] = {
      {"DVPR_QUERY_3", MessageRole::kQuery, QueueEffect::kRequest, "query"},
      {"DVPR_QUERY_ALL", MessageRole::kQuery, QueueEffect::kRequest, "query"},
      {"DVPR_PROBE_0", MessageRole::kQuery, QueueEffect::kRequest, "query"},
      {"DVPR_STORE_12", MessageRole::kQuery, QueueEffect::kNone, "query"},  // kept, never answered
      {"DVPR_MATCH_1", MessageRole::kReply, QueueEffect::kAnswer, "reply"},
      {"DVPR_BOWQ_2", MessageRole::kQuery, QueueEffect::kRequest, "query"},  // bag-of-words part
      {"DVPR_BOWP_0", MessageRole::kQuery, QueueEffect::kRequest, "query"},  // bow_broadcast
      {"DVPR_BOWM_5", MessageRole::kReply, QueueEffect::kAnswer, "reply"},
      {"DVPR_VREQ_0", MessageRole::kVerifyRequest, QueueEffect::kRequest, "verify request"},
      {"DVPR_VRES_4", MessageRole::kVerifyResult, QueueEffect::kAnswer, "verify result"},
      {"DVPR_SAMPLE_0", MessageRole::kRecluster, QueueEffect::kNone, "re-clustering"},
      {"DVPR_TABLE", MessageRole::kRecluster, QueueEffect::kNone, "re-clustering"},
      {"DVPR_MIGRATE_7", MessageRole::kRecluster, QueueEffect::kNone, "re-clustering"},
      {"DVPR_STATUS", MessageRole::kOther, QueueEffect::kNone, "other"},  // heartbeats
      {"DVPR_HEARTBEAT_2", MessageRole::kOther, QueueEffect::kNone, "other"},
      {"DVPR_TABLES", MessageRole::kOther, QueueEffect::kNone, "other"},
      {"", MessageRole::kOther, QueueEffect::kNone, "other"},
  };
  for (const Case& c : cases) {
    EXPECT_EQ(channels::RoleOf(c.channel), c.role) << c.channel;
    EXPECT_EQ(QueueEffectOfChannel(c.channel), c.queue) << c.channel;
    EXPECT_EQ(RoleName(channels::RoleOf(c.channel)), c.name) << c.channel;
  }
}

}  // namespace
}  // namespace dvpr::replay
