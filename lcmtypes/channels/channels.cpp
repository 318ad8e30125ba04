#include "lcmtypes/channels/channels.h"

#include <array>
#include <stdexcept>

#include <dvpr/agent_status_t.hpp>
#include <dvpr/bow_match_t.hpp>
#include <dvpr/bow_query_t.hpp>
#include <dvpr/centroid_table_t.hpp>
#include <dvpr/descriptor_batch_t.hpp>
#include <dvpr/match_t.hpp>
#include <dvpr/query_t.hpp>
#include <dvpr/routing_hello_t.hpp>
#include <dvpr/routing_topology_t.hpp>
#include <dvpr/verify_request_t.hpp>
#include <dvpr/verify_result_t.hpp>

namespace dvpr::channels {

namespace {

using K = ChannelKind;
using R = MessageRole;

// Constant-initialised, so the agents' channel constants (agents/messages/channels.h) may be made from it
// during static initialisation.
constexpr std::array<ChannelSpec, kChannelKinds> kCatalogue = {{
    {K::kQuery, "DVPR_QUERY_", true, R::kQuery, true, false},
    {K::kProbe, "DVPR_PROBE_", true, R::kQuery, true, false},
    {K::kStore, "DVPR_STORE_", true, R::kQuery, false, false},
    // The name predates the roles and stays: it is counted in the bytes.
    {K::kQueryAll, "DVPR_QUERY_ALL", false, R::kQuery, true, false},
    {K::kMatch, "DVPR_MATCH_", true, R::kReply, false, true},
    {K::kVerifyRequest, "DVPR_VREQ_", true, R::kVerifyRequest, true, false},
    {K::kVerifyResult, "DVPR_VRES_", true, R::kVerifyResult, false, true},
    {K::kBowQuery, "DVPR_BOWQ_", true, R::kQuery, true, false},
    {K::kBowProbe, "DVPR_BOWP_", true, R::kQuery, true, false},
    {K::kBowMatch, "DVPR_BOWM_", true, R::kReply, false, true},
    {K::kSample, "DVPR_SAMPLE_", true, R::kRecluster, false, false},
    {K::kMigrate, "DVPR_MIGRATE_", true, R::kRecluster, false, false},
    {K::kTable, "DVPR_TABLE", false, R::kRecluster, false, false},
    // Heartbeats count as "other" in the result files: they are the team's upkeep, not a step
    // of the method.
    {K::kStatus, "DVPR_STATUS", false, R::kOther, false, false},
    // link_state routing's beacons: the network's upkeep, "other" in the by-role columns (whose
    // set the golden files fix); radio.csv counts them apart (routing_transmissions, _bytes).
    {K::kHello, "DVPR_HELLO", false, R::kOther, false, false},
    {K::kTopology, "DVPR_TOPOLOGY", false, R::kOther, false, false},
}};

constexpr bool InKindOrder() {
  for (int i = 0; i < kChannelKinds; ++i) {
    if (static_cast<int>(kCatalogue[static_cast<std::size_t>(i)].kind) != i) return false;
  }
  return true;
}
static_assert(InKindOrder(), "kCatalogue lists the channels in ChannelKind order");

}  // namespace

std::span<const ChannelSpec> AllChannels() { return kCatalogue; }

const ChannelSpec& SpecOf(ChannelKind kind) {
  const auto i = static_cast<std::size_t>(kind);
  if (i >= kCatalogue.size()) throw std::invalid_argument("channels: unknown channel kind " + std::to_string(i));
  return kCatalogue[i];
}

std::string_view LcmTypeOf(ChannelKind kind) {
  switch (kind) {
    case K::kQuery:
    case K::kProbe:
    case K::kStore:
    case K::kQueryAll: return query_t::getTypeName();
    case K::kMatch: return match_t::getTypeName();
    case K::kVerifyRequest: return verify_request_t::getTypeName();
    case K::kVerifyResult: return verify_result_t::getTypeName();
    case K::kBowQuery:
    case K::kBowProbe: return bow_query_t::getTypeName();
    case K::kBowMatch: return bow_match_t::getTypeName();
    case K::kSample:
    case K::kMigrate: return descriptor_batch_t::getTypeName();
    case K::kTable: return centroid_table_t::getTypeName();
    case K::kStatus: return agent_status_t::getTypeName();
    case K::kHello: return routing_hello_t::getTypeName();
    case K::kTopology: return routing_topology_t::getTypeName();
  }
  throw std::invalid_argument("channels: unknown channel kind " + std::to_string(static_cast<int>(kind)));
}

std::string ChannelName(ChannelKind kind, int robot) {
  const ChannelSpec& spec = SpecOf(kind);
  if (spec.unicast != (robot >= 0)) {
    throw std::invalid_argument("channels: " + std::string(spec.name) +
                                (spec.unicast ? " needs a robot id" : " is the team's, it takes no robot id"));
  }
  return spec.unicast ? std::string(spec.name) + std::to_string(robot) : std::string(spec.name);
}

std::optional<ChannelKind> KindOf(std::string_view channel) {
  // Whole names first: DVPR_QUERY_ALL also starts with the query prefix.
  for (const ChannelSpec& spec : kCatalogue) {
    if (!spec.unicast && channel == spec.name) return spec.kind;
  }
  for (const ChannelSpec& spec : kCatalogue) {
    if (spec.unicast && channel.starts_with(spec.name)) return spec.kind;
  }
  return std::nullopt;
}

MessageRole RoleOf(std::string_view channel) {
  const auto kind = KindOf(channel);
  return kind ? SpecOf(*kind).role : MessageRole::kOther;
}

}  // namespace dvpr::channels
