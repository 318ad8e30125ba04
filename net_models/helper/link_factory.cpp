#include "net_models/helper/link_factory.h"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>
#include <utility>

#include "net_models/core/param_checks.h"
#include "net_models/medium/csma_link.h"
#include "net_models/medium/ideal_link.h"
#include "net_models/medium/point_to_point_link.h"
#include "net_models/medium/radio_link.h"
#include "net_models/medium/shared_medium_link.h"

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

RadioLinkParams ToRadio(const NetworkModelParams& p) { return RadioLinkParams{p.bandwidth, p.latency, p.queue_packets}; }

CsmaParams ToCsma(const NetworkModelParams& p) { return CsmaParams{p.bandwidth, p.latency, p.queue_packets}; }

WifiParams ToWifi(const NetworkModelParams& p) {
  WifiParams w = p.wifi;
  w.queue_packets = p.queue_packets;
  return w;
}

constexpr std::array<std::pair<LinkModelKind, std::string_view>, 6> kNames{{
    {LinkModelKind::kIdeal, "ideal"},
    {LinkModelKind::kPointToPoint, "point_to_point"},
    {LinkModelKind::kSharedMedium, "shared_medium"},
    {LinkModelKind::kRadio, "radio"},
    {LinkModelKind::kCsma, "csma"},
    {LinkModelKind::kWifi, "wifi"},
}};

void ValidateLink(const LinkOverrideParams& o, std::size_t i, LinkModelKind model, int nodes) {
  const std::string field = "links[" + std::to_string(i) + "]";
  const std::string pair = std::to_string(o.src.value) + "->" + std::to_string(o.dst.value);
  if (o.src.value < 0 || o.src.value >= nodes || o.dst.value < 0 || o.dst.value >= nodes || o.src == o.dst) {
    InvalidParam(field, pair + " is not a link between two of the " + std::to_string(nodes) + " robots");
  }
  if (model != LinkModelKind::kPointToPoint && (o.bandwidth || o.latency)) {
    InvalidParam(field, "bandwidth/latency overrides need model point_to_point, not " + std::string(ToString(model)));
  }
  if (o.bandwidth) {
    CheckPositiveRate(field + ".bandwidth", *o.bandwidth);
    CheckInRange(field + ".bandwidth", *o.bandwidth, NetworkModelParams::kMinBandwidth,
                 NetworkModelParams::kMaxBandwidth);
  }
  if (o.latency) {
    CheckNonNegativeDuration(field + ".latency", *o.latency);
    CheckInRange(field + ".latency", *o.latency, SimTime::Zero(), NetworkModelParams::kMaxLatency);
  }
  if (o.loss) ValidateNested(field + ".loss.", [&] { o.loss->Validate(); });
}

}  // namespace

bool Contends(LinkModelKind kind) { return kind == LinkModelKind::kCsma || kind == LinkModelKind::kWifi; }

PropagationParams PropagationOf(const NetworkModelParams& params) {
  if (params.propagation) return *params.propagation;
  return params.model == LinkModelKind::kRadio ? PropagationParams::Radio() : PropagationParams{};
}

WireParams WireOf(const NetworkModelParams& params) {
  switch (params.model) {
    case LinkModelKind::kCsma: return LinkWire(params.wire, LinkFraming::kEthernetDix);
    case LinkModelKind::kWifi: return LinkWire(params.wire, LinkFraming::kWifi);
    default: return LinkWire(params.wire, LinkFraming::kPpp);
  }
}

LinkModelKind ParseLinkModelKind(std::string_view name) {
  std::string expected;
  for (const auto& [kind, spelling] : kNames) {
    if (spelling == name) return kind;
    expected += (expected.empty() ? "" : ", ") + std::string(spelling);
  }
  throw std::invalid_argument("unknown value '" + std::string(name) + "' (expected one of: " + expected + ")");
}

std::string_view ToString(LinkModelKind kind) {
  for (const auto& [k, spelling] : kNames) {
    if (k == kind) return spelling;
  }
  return "unknown";
}

// The model parameters are checked even for "ideal", so a typo is caught before a sweep
// switches models.
void NetworkModelParams::Validate(int nodes) const {
  if (nodes <= 0) InvalidParam("nodes", "a network needs at least one node, got " + std::to_string(nodes));
  CheckPositiveRate("bandwidth", bandwidth);
  CheckInRange("bandwidth", bandwidth, kMinBandwidth, kMaxBandwidth);
  CheckNonNegativeDuration("latency", latency);
  CheckInRange("latency", latency, SimTime::Zero(), kMaxLatency);
  CheckNonNegativeCount("queue_packets", queue_packets);
  CheckInRange("queue_packets", queue_packets, 1, kMaxQueuePackets);
  wire.Validate();  // its fields (mtu, link_framing) sit at the top of a network section
  ValidateNested("loss.", [&] { loss.Validate(); });
  for (std::size_t i = 0; i < links.size(); ++i) ValidateLink(links[i], i, model, nodes);
  if (Contends(model)) {
    // The channel's loss draws each frame's fate when the medium has decided it at send time; a
    // contending MAC settles its frames later (link_model.h), past the channel's loss.
    const bool pair_loss = std::any_of(links.begin(), links.end(), [](const LinkOverrideParams& o) { return o.loss; });
    if (loss.model != LossModelKind::kNone || pair_loss) {
      InvalidParam("loss", "a loss model needs a medium access that decides at send time, not model " +
                               std::string(ToString(model)));
    }
  }
  const PropagationParams propagation_used = PropagationOf(*this);
  if (propagation_used.NeedsPositions() && model != LinkModelKind::kRadio && model != LinkModelKind::kWifi) {
    InvalidParam("propagation", std::string(ToString(propagation_used.kind)) +
                                    " applies to models radio and wifi, not model " + std::string(ToString(model)));
  }
  ValidateNested("radio.", [&] { propagation_used.Validate(); });
  if (model == LinkModelKind::kWifi) ValidateNested("wifi.", [&] { ToWifi(*this).Validate(); });
  ValidateNested("disconnected.", [&] { disconnected.Validate(); });
  if (next_hop == NextHopKind::kLinkState) ValidateNested("routing.", [&] { link_state.Validate(); });
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
    case LinkModelKind::kRadio: link = std::make_unique<RadioLink>(ToRadio(params), nodes); break;
    case LinkModelKind::kCsma: link = std::make_unique<CsmaLink>(ToCsma(params), nodes, run_seed); break;
    case LinkModelKind::kWifi: link = std::make_unique<WifiLink>(ToWifi(params), nodes, run_seed); break;
  }
  return link;
}

}  // namespace dvpr
