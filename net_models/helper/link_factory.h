#pragma once
// Building the configured link model: the `network:` section of a config,
// already typed (experiments/ parses YAML; nothing here sees it).
#include <cstdint>
#include <memory>
#include <optional>
#include <string_view>
#include <vector>

#include "net_models/core/wire_format.h"
#include "net_models/link/link_model.h"
#include "net_models/medium/wifi_link.h"
#include "net_models/network/disconnected_params.h"
#include "net_models/propagation/loss_params.h"
#include "net_models/propagation/propagation_params.h"
#include "net_models/link_state/link_state_params.h"
#include "net_models/routing/next_hop_routing.h"

namespace dvpr {

// shared_medium is the ideal bus (first come, first served, no gaps, no contention): the
// optimistic bound of csma, ns-3's CSMA (csma_link.h).
enum class LinkModelKind { kIdeal, kPointToPoint, kSharedMedium, kRadio, kCsma, kWifi };

// The one spelling of each kind: "ideal" | "point_to_point" | "shared_medium" | "radio" | "csma" |
// "wifi". Parse throws
// std::invalid_argument "unknown value '<name>' (expected one of: ...)" for anything else.
LinkModelKind ParseLinkModelKind(std::string_view name);
std::string_view ToString(LinkModelKind kind);

// A directed pair whose parameters differ from the defaults. Bandwidth and
// latency overrides need the point_to_point model; loss overrides work on all.
struct LinkOverrideParams {
  NodeId src;
  NodeId dst;
  std::optional<DataRate> bandwidth;
  std::optional<SimTime> latency;
  std::optional<LossParams> loss;
  bool operator==(const LinkOverrideParams&) const = default;
};

struct NetworkModelParams {
  // The valid ranges (docs/config.md), for the defaults and every link override. With them the
  // largest message (1 GiB request, fragmented) takes about 2e16 ns to send and a latency at most
  // 8.64e13 ns, so sums of a few of them with a frame's time stay far inside int64 nanoseconds.
  static constexpr DataRate kMinBandwidth = DataRate::Kbps(1);
  static constexpr DataRate kMaxBandwidth = DataRate::Gbps(1000);
  static constexpr SimTime kMaxLatency = SimTime::Millis(24LL * 3600 * 1000);  // 24 h
  static constexpr int kMaxQueuePackets = 1 << 30;

  LinkModelKind model = LinkModelKind::kPointToPoint;
  DataRate bandwidth = DataRate::Mbps(10);
  SimTime latency = SimTime::Millis(2);
  int queue_packets = 100;
  WireParams wire;  // mtu, link framing
  LossParams loss;  // for every pair unless overridden
  std::vector<LinkOverrideParams> links;
  // Who hears whom (the stack's propagation; radio and wifi): unset, the medium's own
  // (PropagationOf).
  std::optional<PropagationParams> propagation;
  WifiParams wifi;    // model wifi: its rates (queue_packets is the one above)
  NextHopKind next_hop = NextHopKind::kDirect;  // which way a copy goes (the stack's next hop)
  LinkStateParams link_state;  // routing link_state: its beacon periods
  DisconnectedParams disconnected;  // a copy without a route: dropped, or held (store-and-forward)

  // Throws std::invalid_argument "<field>: ..." naming the value, with the
  // fields spelled as in a config's network section ("bandwidth", "mtu",
  // "loss.p", "links[0].latency"): a bandwidth, latency or queue outside its
  // range above, an MTU outside WireParams', a probability outside [0, 1], an override naming a
  // node outside [0, nodes) or its own link, a bandwidth/latency override
  // on a model other than point_to_point, a propagation over positions on a model other than
  // radio and wifi ("propagation") or with parameters out of range ("radio.range"), a wifi without a rate or with one outside 802.11a's ("wifi.rate"), or a
  // loss model on a contending model ("loss").
  void Validate(int nodes) const;
  bool operator==(const NetworkModelParams&) const = default;
};

// A contending medium access: it runs events of its own and settles copies later (link_model.h).
bool Contends(LinkModelKind kind);

// Who hears whom on a network of these parameters, the one place that decides it: the given
// propagation, else the medium's own (a radio's: range 200 m; every other medium's: the full mesh).
PropagationParams PropagationOf(const NetworkModelParams& params);

// The wire format of a network of these parameters: params.wire with its model's framing (PPP;
// DIX Ethernet for csma; 802.11 for wifi).
WireParams WireOf(const NetworkModelParams& params);

// The medium access of `params` for `nodes` nodes (validated); run_seed seeds a contending
// model's backoffs. Who hears whom, and the loss, are the channel's, not the medium's: the
// network lends its channel to the medium at Bind (MakeNetworkStack builds its propagation and
// ReceptionLoss).
std::unique_ptr<LinkModel> MakeLinkModel(const NetworkModelParams& params, int nodes, std::uint64_t run_seed);

}  // namespace dvpr
