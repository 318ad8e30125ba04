// The network-side sections of the config: network (with its sweepable lists), verification,
// service, dropout, outputs.
#include <algorithm>
#include <cstdint>
#include <string>

#include "experiments/config/config.h"
#include "experiments/config/config_reader.h"

namespace dvpr::config_detail {

namespace {

// The loss map is flat (`{model: bernoulli, p: 0.01}`): each model's keys are its own struct's
// fields.
LossParams ReadLoss(const Field& f) {
  LossParams l;
  if (!f.present()) return l;
  if (!f.node().IsMap()) f.Fail("expected a map such as {model: none} or {model: bernoulli, p: 0.01}");
  const Field model = f.Child("model");
  if (!model.present()) model.Fail("required (none, bernoulli or gilbert_elliott)");
  l.model = model.Named(ParseLossModelKind);
  switch (l.model) {
    case LossModelKind::kNone:
      f.ExpectMap({"model"});
      break;
    case LossModelKind::kBernoulli:
      f.ExpectMap({"model", "p"});
      if (!f.Child("p").present()) f.Child("p").Fail("required for the bernoulli loss model");
      l.bernoulli.p = f.Child("p").Double();
      break;
    case LossModelKind::kGilbertElliott: {
      f.ExpectMap({"model", "p_good_to_bad", "p_bad_to_good", "loss_good", "loss_bad"});
      for (const char* k : {"p_good_to_bad", "p_bad_to_good"}) {
        if (!f.Child(k).present()) f.Child(k).Fail("required for the gilbert_elliott loss model");
      }
      GilbertElliottParams& ge = l.gilbert_elliott;
      ge.p_good_to_bad = f.Child("p_good_to_bad").Double();
      ge.p_bad_to_good = f.Child("p_bad_to_good").Double();
      if (auto c = f.Child("loss_good"); c.present()) ge.loss_good = c.Double();
      if (auto c = f.Child("loss_bad"); c.present()) ge.loss_bad = c.Double();
      break;
    }
  }
  f.Validate(l);
  return l;
}

DataRate ReadBandwidth(const Field& f) {
  return f.Rate(NetworkModelParams::kMinBandwidth, NetworkModelParams::kMaxBandwidth);
}

SimTime ReadLatency(const Field& f) { return f.Duration(SimTime::Zero(), NetworkModelParams::kMaxLatency); }

// Whether each link lies in the team is checked per run (NetworkModelParams::Validate), as
// the team size is swept.
std::vector<LinkOverrideParams> ReadLinks(const Field& f) {
  std::vector<LinkOverrideParams> links;
  if (!f.present()) return links;
  if (!f.node().IsSequence()) f.Fail("expected a list of {src, dst, bandwidth, latency, loss}");
  if (f.node().size() == 0) return links;  // `links: []`, as EmitConfig writes no overrides
  for (const Field& item : f.Items()) {
    item.ExpectMap({"src", "dst", "bandwidth", "latency", "loss"});
    LinkOverrideParams o;
    o.src = NodeId(static_cast<std::int32_t>(item.Child("src").Int(0, 100000)));
    o.dst = NodeId(static_cast<std::int32_t>(item.Child("dst").Int(0, 100000)));
    if (o.src == o.dst) item.Child("dst").Fail("must differ from src");
    if (auto c = item.Child("bandwidth"); c.present()) o.bandwidth = ReadBandwidth(c);
    if (auto c = item.Child("latency"); c.present()) o.latency = ReadLatency(c);
    if (auto c = item.Child("loss"); c.present()) o.loss = ReadLoss(c);
    links.push_back(o);
  }
  return links;
}

template <typename T, typename ReadOne>
std::vector<T> ReadList(const Field& f, ReadOne read_one) {
  std::vector<T> values;
  for (const Field& item : f.Items()) {
    T v = read_one(item);
    if (std::find(values.begin(), values.end(), v) != values.end()) item.Fail("listed twice");
    values.push_back(v);
  }
  return values;
}

double ReadRange(const Field& f) {
  const std::string& text = f.String();
  double metres = 0;
  try {
    metres = ParseMeters(text);
  } catch (const std::invalid_argument& e) {
    f.Fail(std::string("expected a length with a unit, e.g. 200m (") + e.what() + ")");
  }
  if (metres == 0 && NonZeroNumber(text)) {
    f.Fail(text + " rounds to 0 at the resolution of lengths (1mm), below the smallest allowed value 1mm");
  }
  if (!(metres > 0) || metres > PropagationParams::kMaxRangeM) f.Fail("must be in (0m, 1000000km], got " + text);
  return metres;
}

LogDistanceParams ReadLogDistance(const Field& f) {
  LogDistanceParams l;
  if (!f.present()) return l;
  if (!f.node().IsMap()) f.Fail("expected a map such as {exponent: 3.0, sensitivity_dbm: -82}");
  f.ExpectMap({"exponent", "reference_distance", "reference_loss_db", "tx_power_dbm", "sensitivity_dbm",
               "shadowing_db", "shadowing_window"});
  if (auto c = f.Child("exponent"); c.present()) l.exponent = c.Double();
  if (auto c = f.Child("reference_distance"); c.present()) l.reference_distance_m = ReadRange(c);
  if (auto c = f.Child("reference_loss_db"); c.present()) l.reference_loss_db = c.Double();
  if (auto c = f.Child("tx_power_dbm"); c.present()) l.tx_power_dbm = c.Double();
  if (auto c = f.Child("sensitivity_dbm"); c.present()) l.sensitivity_dbm = c.Double();
  if (auto c = f.Child("shadowing_db"); c.present()) l.shadowing_db = c.Double();
  if (auto c = f.Child("shadowing_window"); c.present()) {
    l.shadowing_window_s = c.Duration(SimTime::Millis(1), SimTime::Seconds(86400)).ToSeconds();
  }
  return l;
}

// One radio map: {propagation, range, log_distance}; `range` may be a list (one variant each).
std::vector<PropagationParams> ReadRadioMap(const Field& f) {
  if (!f.node().IsMap()) f.Fail("expected a map such as {propagation: range, range: 200m}");
  f.ExpectMap({"propagation", "range", "log_distance"});
  PropagationParams base = PropagationParams::Radio();
  if (auto c = f.Child("propagation"); c.present()) {
    base.kind = c.Named([](std::string_view name) { return ParsePropagationKind(name); });
  }
  const Field range = f.Child("range");
  const Field log_distance = f.Child("log_distance");
  if (base.kind == PropagationKind::kLogDistance && range.present()) {
    range.Fail("applies to propagation range; log_distance's reach follows from its own keys");
  }
  if (base.kind == PropagationKind::kRange && log_distance.present()) {
    log_distance.Fail("applies to propagation log_distance, not range");
  }
  base.log_distance = ReadLogDistance(log_distance);
  std::vector<PropagationParams> out;
  if (base.kind == PropagationKind::kRange && range.present()) {
    for (const double metres : ReadList<double>(range, ReadRange)) {
      PropagationParams r = base;
      r.range_m = metres;
      out.push_back(r);
    }
  } else {
    out.push_back(base);
  }
  for (const PropagationParams& r : out) f.Validate(r);
  return out;
}

// network.radio: one radio map, or a list of them (a range sweep beside a log_distance radio):
// one variant per entry, none twice.
std::vector<PropagationParams> ReadRadio(const Field& f) {
  if (!f.present()) return {PropagationParams::Radio()};
  if (!f.node().IsSequence()) return ReadRadioMap(f);
  std::vector<PropagationParams> out;
  for (const Field& item : f.Items()) {
    for (const PropagationParams& r : ReadRadioMap(item)) {
      if (std::find(out.begin(), out.end(), r) != out.end()) item.Fail("repeats a radio listed before");
      out.push_back(r);
    }
  }
  return out;
}

// A key that is a kind's name alone, or a map of `keys` that names its kind: the kind, parsed by
// `parse`. The caller reads a map's other keys (a name has none). `expected`: the error for a key
// that is neither; kind_hint: the kind a map usually names.
template <typename Parse>
auto ReadKindOrMap(const Field& f, Parse parse, std::initializer_list<std::string_view> keys, const char* expected,
                   const char* kind_hint) -> decltype(parse(std::string_view())) {
  if (f.node().IsScalar()) return f.Named(parse);
  if (!f.node().IsMap()) f.Fail(expected);
  f.ExpectMap(keys);
  const Field kind = f.Child("kind");
  if (!kind.present()) f.Fail(std::string("a map needs its kind (") + kind_hint + ")");
  return kind.Named(parse);
}

// network.disconnected: drop | store_and_forward | {kind: store_and_forward, hold_bytes, hold_time}.
DisconnectedParams ReadDisconnected(const Field& f) {
  DisconnectedParams d;
  d.kind = ReadKindOrMap(f, ParseDisconnectedKind, {"kind", "hold_bytes", "hold_time"},
                         "expected drop, or a map such as {kind: store_and_forward, hold_bytes: 10MB, hold_time: 60s}",
                         "store_and_forward");
  if (f.node().IsScalar()) return d;
  const Field hold_bytes = f.Child("hold_bytes");
  const Field hold_time = f.Child("hold_time");
  if (d.kind == DisconnectedKind::kDrop) {
    if (hold_bytes.present()) hold_bytes.Fail("applies to store_and_forward; drop holds nothing");
    if (hold_time.present()) hold_time.Fail("applies to store_and_forward; drop holds nothing");
  }
  if (hold_bytes.present()) {
    d.hold_bytes = hold_bytes.Size(Bytes(1), DisconnectedParams::kMaxHoldBytes, /*plain_integer_is_bytes=*/false);
  }
  if (hold_time.present()) d.hold_time = hold_time.Duration(SimTime::Nanos(1), DisconnectedParams::kMaxHoldTime);
  f.Validate(d);
  return d;
}

// One entry of network.routing: direct | shortest_path | link_state |
// {kind: link_state, hello, topology}.
NextHopEntry ReadNextHopEntry(const Field& f) {
  NextHopEntry e;
  e.kind = ReadKindOrMap(
      f, ParseNextHopKind, {"kind", "hello", "topology"},
      "expected direct, shortest_path, link_state or a map such as {kind: link_state, hello: 2s, topology: 5s}",
      "link_state");
  if (f.node().IsScalar()) return e;
  const Field hello = f.Child("hello");
  const Field topology = f.Child("topology");
  if (e.kind != NextHopKind::kLinkState) {
    const std::string why = "applies to link_state; " + std::string(ToString(e.kind)) + " sends no beacons";
    if (hello.present()) hello.Fail(why);
    if (topology.present()) topology.Fail(why);
  }
  if (hello.present()) e.link_state.hello = hello.Duration(SimTime::Nanos(1), LinkStateParams::kMaxPeriod);
  if (topology.present()) e.link_state.topology = topology.Duration(SimTime::Nanos(1), LinkStateParams::kMaxPeriod);
  f.Validate(e.link_state);
  return e;
}

// network.routing: one entry or a list of them (one radio variant each), none twice.
std::vector<NextHopEntry> ReadNextHop(const Field& f) {
  std::vector<NextHopEntry> out;
  if (f.node().IsSequence()) {
    for (const Field& e : f.Items()) {
      out.push_back(ReadNextHopEntry(e));
      if (std::find(out.begin(), out.end() - 1, out.back()) != out.end() - 1) e.Fail("is listed twice");
    }
  } else {
    out.push_back(ReadNextHopEntry(f));
  }
  return out;
}

bool Lists(const NetworkConfig& n, LinkModelKind kind) {
  return std::find(n.model.begin(), n.model.end(), kind) != n.model.end();
}

// network.wifi: {rate, basic_rate, propagation: full_mesh | radio}; rate required. True when its
// propagation is the radio's (network.radio's entries, read after it).
bool ReadWifi(const Field& f, NetworkConfig& n) {
  const char* rates = "one of 6, 9, 12, 18, 24, 36, 48, 54 Mbit/s";
  if (!f.present()) {
    if (Lists(n, LinkModelKind::kWifi)) {
      f.Fail(std::string("model wifi needs this section with its data rate: {rate: 54Mbps}, ") + rates);
    }
    return false;
  }
  if (!Lists(n, LinkModelKind::kWifi)) f.Fail("applies to model wifi, which network.model does not list");
  if (!f.node().IsMap()) f.Fail("expected a map such as {rate: 54Mbps}");
  f.ExpectMap({"rate", "basic_rate", "propagation"});
  const Field rate = f.Child("rate");
  if (!rate.present()) rate.Fail(std::string("model wifi needs a data rate: ") + rates);
  n.wifi.rate = rate.Rate(NetworkModelParams::kMinBandwidth, NetworkModelParams::kMaxBandwidth);
  if (auto c = f.Child("basic_rate"); c.present()) {
    n.wifi.basic_rate = c.Rate(NetworkModelParams::kMinBandwidth, NetworkModelParams::kMaxBandwidth);
  }
  bool over_radio = false;
  if (auto c = f.Child("propagation"); c.present()) {
    over_radio = c.Named([](std::string_view name) {
      if (name == "full_mesh") return false;
      if (name == "radio") return true;
      throw std::invalid_argument("unknown value '" + std::string(name) + "' (expected one of: full_mesh, radio)");
    });
  }
  f.Validate(n.wifi);
  return over_radio;
}

}  // namespace

NetworkConfig ReadNetwork(const Field& f, const SweepConfig& sweep) {
  NetworkConfig n;
  if (!f.present()) return n;
  f.ExpectMap({"model", "bandwidth", "latency", "queue_packets", "mtu", "loss", "links", "radio", "routing",
               "disconnected", "schedule", "wifi"});
  if (auto c = f.Child("model"); c.present()) {
    n.model = ReadList<LinkModelKind>(c, [](const Field& i) { return i.Named(ParseLinkModelKind); });
  }
  if (auto c = f.Child("bandwidth"); c.present()) {
    n.bandwidth = ReadList<DataRate>(c, ReadBandwidth);
  }
  if (auto c = f.Child("latency"); c.present()) {
    n.latency = ReadList<SimTime>(c, ReadLatency);
  }
  if (auto c = f.Child("queue_packets"); c.present()) {
    n.queue_packets =
        ReadList<int>(c, [](const Field& i) { return static_cast<int>(i.Int(1, NetworkModelParams::kMaxQueuePackets)); });
  }
  if (auto c = f.Child("mtu"); c.present()) {
    n.mtu = ReadList<Bytes>(c, [](const Field& i) {
      return i.Size(WireParams::kMinConfigMtu, WireParams::kMaxMtu, /*plain_integer_is_bytes=*/true);
    });
  }
  n.loss = ReadLoss(f.Child("loss"));
  if (n.loss.model != LossModelKind::kNone) {
    for (const LinkModelKind kind : n.model) {
      if (Contends(kind)) {
        f.Child("loss").Fail("a loss model needs a medium access that decides at send time, not model " +
                             std::string(ToString(kind)));
      }
    }
  }
  n.links = ReadLinks(f.Child("links"));
  const bool wifi_over_radio = ReadWifi(f.Child("wifi"), n);
  if (const Field radio = f.Child("radio"); radio.present()) {
    if (!Lists(n, LinkModelKind::kRadio) && !(Lists(n, LinkModelKind::kWifi) && wifi_over_radio)) {
      radio.Fail(Lists(n, LinkModelKind::kWifi)
                     ? "applies to model radio, or wifi with propagation radio (network.wifi.propagation)"
                     : "applies to model radio, which network.model does not list");
    }
    n.radio = ReadRadio(radio);
  }
  if (wifi_over_radio) n.wifi_propagation = n.radio;
  if (const Field c = f.Child("routing"); c.present()) {
    n.routing = ReadNextHop(c);
    const bool routed = std::any_of(n.routing.begin(), n.routing.end(),
                                    [](const NextHopEntry& e) { return e.kind != NextHopKind::kDirect; });
    if (routed && std::find(n.model.begin(), n.model.end(), LinkModelKind::kRadio) == n.model.end()) {
      c.Fail("applies to model radio, which network.model does not list (the other models reach every robot in one hop)");
    }
  }
  if (const Field c = f.Child("disconnected"); c.present()) {
    if (std::find(n.model.begin(), n.model.end(), LinkModelKind::kRadio) == n.model.end()) {
      c.Fail("applies to model radio, which network.model does not list (only a radio loses its routes)");
    }
    n.disconnected = ReadDisconnected(c);
  }
  if (const Field c = f.Child("schedule"); c.present()) {
    n.schedule = c.ExistingFile();
    try {
      n.windows = ReadTalkSchedule(*n.schedule, *std::max_element(sweep.robots.begin(), sweep.robots.end()) - 1);
    } catch (const std::invalid_argument& e) {
      c.Fail(e.what());
    }
  }
  // Store-and-forward holds what routing finds no way for; direct routing always names the
  // destination (one hop, lost out of range if unheard), so it would hold only what a sender
  // sends outside its talk window (network.schedule). Without windows it would silently drop.
  const bool relays = std::any_of(n.routing.begin(), n.routing.end(),
                                  [](const NextHopEntry& e) { return e.kind != NextHopKind::kDirect; });
  if (n.disconnected.kind == DisconnectedKind::kStoreAndForward && !relays && n.windows.empty()) {
    f.Child("disconnected").Fail("store_and_forward holds nothing with network.routing: direct (every copy goes "
                                 "straight to its destination, or is lost out of range): use shortest_path or "
                                 "link_state routing, or a network.schedule, or drop");
  }
  return n;
}

VerificationParams ReadVerification(const Field& f) {
  VerificationParams v;
  if (!f.present()) return v;
  f.ExpectMap({"request_bytes", "max_distance", "bow_max_distance"});
  if (auto c = f.Child("request_bytes"); c.present()) {
    v.request_bytes = c.Size(Bytes(0), VerificationParams::kMaxRequestBytes, /*plain_integer_is_bytes=*/true);
  }
  if (auto c = f.Child("max_distance"); c.present()) {
    v.max_distance = c.Double(0.0, VerificationParams::kMaxDistance);
  }
  if (auto c = f.Child("bow_max_distance"); c.present()) v.bow_max_distance = c.Double(0.0, 1.0);
  f.Validate(v);
  return v;
}

ServiceParams ReadService(const Field& f) {
  ServiceParams s;
  if (!f.present()) return s;
  f.ExpectMap({"fixed", "per_comparison"});
  if (auto c = f.Child("fixed"); c.present()) s.fixed = c.Duration(SimTime::Zero(), ServiceParams::kMaxFixed);
  if (auto c = f.Child("per_comparison"); c.present()) {
    s.per_comparison = c.Duration(SimTime::Zero(), ServiceParams::kMaxPerComparison);
  }
  f.Validate(s);
  return s;
}

std::vector<Dropout> ReadDropout(const Field& f, const SweepConfig& sweep) {
  std::vector<Dropout> out;
  if (!f.present()) return out;
  if (!f.node().IsSequence()) f.Fail("expected a list of {robot, at}");
  if (f.node().size() == 0) return out;  // `dropout: []`, as EmitConfig writes no dropout
  const int largest = *std::max_element(sweep.robots.begin(), sweep.robots.end());
  for (const Field& item : f.Items()) {
    item.ExpectMap({"robot", "at"});
    Dropout d;
    d.robot = static_cast<int>(item.Child("robot").Int(0, largest - 1));
    d.at = item.Child("at").Duration(SimTime::Zero(), Dropout::kMaxAt);
    // Once: a second time would give the robot contradictory failover rows.
    for (std::size_t j = 0; j < out.size(); ++j) {
      if (out[j].robot == d.robot) {
        item.Child("robot").Fail("robot " + std::to_string(d.robot) + " is already dropped by dropout[" +
                                 std::to_string(j) + "]; a robot drops out once");
      }
    }
    out.push_back(d);
  }
  return out;
}

OutputsConfig ReadOutputs(const Field& f, const SweepConfig& sweep, const NetworkConfig& network) {
  OutputsConfig o;
  if (!f.present()) return o;
  f.ExpectMap({"figures", "queries", "messages", "lcm_log", "connectivity", "pr_robots"});
  if (auto c = f.Child("figures"); c.present()) o.figures = c.Bool();
  if (auto c = f.Child("queries"); c.present()) o.queries = c.Bool();
  if (auto c = f.Child("messages"); c.present()) o.messages = c.Bool();
  if (auto c = f.Child("lcm_log"); c.present()) o.lcm_log = c.Bool();
  if (auto c = f.Child("connectivity"); c.present()) {
    o.connectivity = c.Bool();
    const bool radio = std::find(network.model.begin(), network.model.end(), LinkModelKind::kRadio) != network.model.end();
    if (o.connectivity && !radio) {
      c.Fail("needs a network variant of model radio (network.model lists none): robots have positions and ranges "
             "only on the radio");
    }
  }
  if (auto c = f.Child("pr_robots"); c.present()) {
    o.pr_robots = static_cast<int>(c.Int(2, 100000));
    if (std::find(sweep.robots.begin(), sweep.robots.end(), *o.pr_robots) == sweep.robots.end()) {
      c.Fail("must be one of the swept robot counts");
    }
  }
  return o;
}

// failover: {enabled, heartbeat_period, timeout} (docs/failover.md). The re-clustering
// strategies have no failover: asking for it with one of them is an error here, before any run.
FailoverParams ReadFailover(const Field& f, const SweepConfig& sweep) {
  FailoverParams p;
  if (!f.present()) return p;
  f.ExpectMap({"enabled", "heartbeat_period", "timeout"});
  if (auto c = f.Child("enabled"); c.present()) p.enabled = c.Bool();
  if (auto c = f.Child("heartbeat_period"); c.present()) {
    p.heartbeat_period = c.Duration(FailoverParams::kMinPeriod, FailoverParams::kMaxTimeout);
  }
  if (auto c = f.Child("timeout"); c.present()) p.timeout = c.Duration(FailoverParams::kMinPeriod, FailoverParams::kMaxTimeout);
  if (p.timeout <= p.heartbeat_period) {
    f.Child(f.Child("timeout").present() ? "timeout" : "heartbeat_period")
        .Fail("timeout must be longer than heartbeat_period, got " + FormatDuration(p.timeout) + " and " +
              FormatDuration(p.heartbeat_period));
  }
  for (const StrategySpec& s : sweep.strategies) {
    if (p.enabled && s.reclusters()) {
      f.Child("enabled").Fail("'" + s.name + "' re-clusters, which has no failover; list it in a config without");
    }
  }
  return p;
}

}  // namespace dvpr::config_detail
