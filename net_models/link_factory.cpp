#include "net_models/link_factory.h"

#include <stdexcept>
#include <string>

#include "net_models/ideal_link.h"
#include "net_models/lossy_link.h"
#include "net_models/point_to_point_link.h"
#include "net_models/shared_medium_link.h"

namespace dvpr {
namespace {

PointToPointParams ToPointToPoint(const NetworkModelParams& p) {
  PointToPointParams out{p.bandwidth, p.latency, p.queue_packets, {}};
  for (const auto& o : p.links) {
    if (o.bandwidth || o.latency) out.overrides.push_back({o.src, o.dst, o.bandwidth, o.latency});
  }
  return out;
}

SharedMediumParams ToSharedMedium(const NetworkModelParams& p) {
  return SharedMediumParams{p.bandwidth, p.latency, p.queue_packets};
}

std::string PairName(const LinkOverrideParams& o) {
  return std::to_string(o.src.value) + "->" + std::to_string(o.dst.value);
}

}  // namespace

LinkModelKind ParseLinkModelKind(std::string_view name) {
  if (name == "ideal") return LinkModelKind::kIdeal;
  if (name == "point_to_point") return LinkModelKind::kPointToPoint;
  if (name == "shared_medium") return LinkModelKind::kSharedMedium;
  throw std::invalid_argument("network.model = \"" + std::string(name) +
                              "\": unknown network model; expected ideal, point_to_point or shared_medium");
}

std::string_view ToString(LinkModelKind kind) {
  switch (kind) {
    case LinkModelKind::kIdeal: return "ideal";
    case LinkModelKind::kPointToPoint: return "point_to_point";
    case LinkModelKind::kSharedMedium: return "shared_medium";
  }
  return "unknown";
}

void NetworkModelParams::Validate(int nodes) const {
  if (nodes <= 0) throw std::invalid_argument("robots = " + std::to_string(nodes) + ": need at least one robot");
  wire.Validate();
  loss.Validate();
  // The model parameters are checked even for "ideal", so a typo is caught
  // before a sweep switches models.
  ToPointToPoint(*this).Validate(nodes);
  for (const auto& o : links) {
    if (model != LinkModelKind::kPointToPoint && (o.bandwidth || o.latency)) {
      throw std::invalid_argument("network.links " + PairName(o) + ": bandwidth/latency overrides need "
                                  "network.model = point_to_point, not " + std::string(ToString(model)));
    }
    if (o.src.value < 0 || o.src.value >= nodes || o.dst.value < 0 || o.dst.value >= nodes || o.src == o.dst) {
      throw std::invalid_argument("network.links " + PairName(o) + ": not a link between two of the " +
                                  std::to_string(nodes) + " robots");
    }
    if (o.loss) o.loss->Validate();
  }
}

std::unique_ptr<LinkModel> MakeLinkModel(const NetworkModelParams& params, int nodes, std::uint64_t run_seed) {
  params.Validate(nodes);
  std::unique_ptr<LinkModel> link;
  switch (params.model) {
    case LinkModelKind::kIdeal: link = std::make_unique<IdealLink>(); break;
    case LinkModelKind::kPointToPoint:
      link = std::make_unique<PointToPointLink>(ToPointToPoint(params), nodes);
      break;
    case LinkModelKind::kSharedMedium:
      link = std::make_unique<SharedMediumLink>(ToSharedMedium(params), nodes);
      break;
  }
  std::vector<PairLossOverride> loss_overrides;
  for (const auto& o : params.links) {
    if (o.loss) loss_overrides.push_back({o.src, o.dst, *o.loss});
  }
  if (params.loss.model == LossModelKind::kNone && loss_overrides.empty()) return link;
  return std::make_unique<LossyLink>(std::move(link), nodes, params.loss, loss_overrides, run_seed);
}

}  // namespace dvpr
