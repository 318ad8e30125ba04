// ExperimentConfig -> YAML: every key written (verification.bow_max_distance only where it can
// matter or was changed, EmitRest), in the order of docs/design.md section 7, numbers in
// their shortest round-trip form, so the file parses back to an equal config.
#include <algorithm>
#include <charconv>
#include <string>
#include <string_view>

#include <yaml-cpp/yaml.h>

#include "experiments/config/config.h"
#include "experiments/config/utc_instant.h"

namespace dvpr {

namespace {

std::string Num(double v) {
  char buf[64];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, end);
}

// Short lists of scalars read better on one line: [1Mbps, 10Mbps].
template <typename T, typename Fn>
void EmitList(YAML::Emitter& out, const std::vector<T>& values, Fn to_string) {
  out << YAML::Flow << YAML::BeginSeq;
  for (const auto& v : values) out << to_string(v);
  out << YAML::EndSeq;
}

std::string Name(std::string_view name) { return std::string(name); }

void EmitLoss(YAML::Emitter& out, const LossParams& l) {
  out << YAML::Flow << YAML::BeginMap << YAML::Key << "model" << YAML::Value << Name(ToString(l.model));
  if (l.model == LossModelKind::kBernoulli) out << YAML::Key << "p" << YAML::Value << Num(l.bernoulli.p);
  if (l.model == LossModelKind::kGilbertElliott) {
    const GilbertElliottParams& ge = l.gilbert_elliott;
    out << YAML::Key << "p_good_to_bad" << YAML::Value << Num(ge.p_good_to_bad)
        << YAML::Key << "p_bad_to_good" << YAML::Value << Num(ge.p_bad_to_good)
        << YAML::Key << "loss_good" << YAML::Value << Num(ge.loss_good)
        << YAML::Key << "loss_bad" << YAML::Value << Num(ge.loss_bad);
  }
  out << YAML::EndMap;
}

// dataset.scenario and dataset.trajectories, only for a planned team (the paper's split writes
// neither, so its config.yaml is what it was).
void EmitTeamPlan(YAML::Emitter& out, const DatasetConfig& d) {
  const ScenarioSpec& s = d.scenario;
  if (s.kind != ScenarioKind::kSplit) {
    out << YAML::Key << "scenario" << YAML::Value << YAML::Flow << YAML::BeginMap << YAML::Key << "kind"
        << YAML::Value << std::string(ToString(s.kind));
    if (s.offset_s > 0) out << YAML::Key << "offset" << YAML::Value << FormatDuration(SimTime::Seconds(s.offset_s));
    if (s.kind == ScenarioKind::kRandomRoutes) {
      out << YAML::Key << "length" << YAML::Value << s.length << YAML::Key << "seed" << YAML::Value << s.seed;
    }
    out << YAML::EndMap;
  }
  if (d.trajectories.empty()) return;
  out << YAML::Key << "trajectories" << YAML::Value << YAML::BeginSeq;
  for (const TrajectorySource& t : d.trajectories) {
    out << YAML::Flow << YAML::BeginMap << YAML::Key << "poses" << YAML::Value << t.poses.string() << YAML::Key
        << "format" << YAML::Value
        << std::string(kTrajectoryFormatNames[static_cast<std::size_t>(t.format)]) << YAML::Key << "start" << YAML::Value
        << FormatDuration(SimTime::Seconds(t.start_s));
    if (t.fps > 0) out << YAML::Key << "fps" << YAML::Value << Num(t.fps);
    if (t.times) out << YAML::Key << "times" << YAML::Value << t.times->string();
    out << YAML::Key << "frame" << YAML::Value << t.frame;
    if (t.descriptors) out << YAML::Key << "descriptors" << YAML::Value << t.descriptors->string();
    out << YAML::EndMap;
  }
  out << YAML::EndSeq;
}

void EmitDataset(YAML::Emitter& out, const DatasetConfig& d) {
  out << YAML::Key << "dataset" << YAML::Value << YAML::BeginMap;
  out << YAML::Key << "source" << YAML::Value << Name(ToString(d.source));
  if (!d.poses.empty()) out << YAML::Key << "poses" << YAML::Value << d.poses.string();
  if (d.descriptors) out << YAML::Key << "descriptors" << YAML::Value << d.descriptors->string();
  out << YAML::Key << "bin_width" << YAML::Value << d.bin_width;
  out << YAML::Key << "dim" << YAML::Value << d.dim;
  out << YAML::Key << "fps" << YAML::Value << Num(d.fps);
  out << YAML::Key << "frames" << YAML::Value
      << (d.frames ? std::to_string(*d.frames) : std::string("all"));
  const auto& k = d.synthetic;
  out << YAML::Key << "synthetic" << YAML::Value << YAML::BeginMap
      << YAML::Key << "place_features" << YAML::Value << k.place_features
      << YAML::Key << "length_scale_min_m" << YAML::Value << Num(k.length_scale_min_m)
      << YAML::Key << "length_scale_max_m" << YAML::Value << Num(k.length_scale_max_m)
      << YAML::Key << "heading_scale" << YAML::Value << Num(k.heading_scale)
      << YAML::Key << "heading_fraction" << YAML::Value << Num(k.heading_fraction)
      << YAML::Key << "variance_decay" << YAML::Value << Num(k.variance_decay)
      << YAML::Key << "noise" << YAML::Value << Num(k.noise)
      << YAML::Key << "appearance_change" << YAML::Value << Num(k.appearance_change)
      << YAML::Key << "appearance_time_scale_frames" << YAML::Value
      << Num(k.appearance_time_scale_frames)
      << YAML::Key << "environment_offset" << YAML::Value << Num(k.environment_offset)
      << YAML::EndMap;
  if (d.bow) out << YAML::Key << "bow" << YAML::Value << d.bow->string();
  if (d.synthetic_bow) {
    const auto& b = *d.synthetic_bow;
    out << YAML::Key << "synthetic_bow" << YAML::Value << YAML::Flow << YAML::BeginMap
        << YAML::Key << "features" << YAML::Value << b.features
        << YAML::Key << "vocabulary" << YAML::Value << b.vocabulary
        << YAML::Key << "landmark_density" << YAML::Value << Num(b.landmark_density)
        << YAML::Key << "range_m" << YAML::Value << Num(b.range_m)
        << YAML::Key << "field_of_view_deg" << YAML::Value << Num(b.field_of_view_deg)
        << YAML::Key << "common_words" << YAML::Value << b.common_words
        << YAML::Key << "common_share" << YAML::Value << Num(b.common_share)
        << YAML::Key << "view_sector_deg" << YAML::Value << Num(b.view_sector_deg) << YAML::EndMap;
  }
  EmitTeamPlan(out, d);
  out << YAML::EndMap;
}

void EmitTraining(YAML::Emitter& out, const TrainingConfig& t) {
  out << YAML::Key << "training" << YAML::Value << YAML::BeginMap;
  out << YAML::Key << "source" << YAML::Value << Name(ToString(t.source));
  if (t.descriptors) out << YAML::Key << "descriptors" << YAML::Value << t.descriptors->string();
  const RunCentroidParams& rc = t.run_centroids;
  if (!rc.centroids_pattern.empty()) out << YAML::Key << "centroids" << YAML::Value << rc.centroids_pattern;
  out << YAML::Key << "clusters_per_robot" << YAML::Value << rc.clusters_per_robot;
  out << YAML::Key << "synthetic" << YAML::Value << YAML::Flow << YAML::BeginMap
      << YAML::Key << "samples" << YAML::Value << t.synthetic.samples
      << YAML::Key << "environments" << YAML::Value << t.synthetic.environments
      << YAML::Key << "training_area_m" << YAML::Value << Num(t.synthetic.training_area_m)
      << YAML::EndMap;
  out << YAML::EndMap;
}

void EmitSweep(YAML::Emitter& out, const SweepConfig& s) {
  out << YAML::Key << "robots" << YAML::Value;
  EmitList(out, s.robots, [](int n) { return n; });
  out << YAML::Key << "runs" << YAML::Value << s.runs;
  out << YAML::Key << "protocols" << YAML::Value;
  EmitList(out, s.protocols, [](const std::string& x) { return x; });
  out << YAML::Key << "strategies" << YAML::Value;
  EmitList(out, s.strategies, [](const StrategySpec& x) { return x.name; });
}

// The entries differ only in range (ReadRadio), so one map with the list of ranges reads back.
// One radio map: a range radio with its ranges (all of `radio`), or one log_distance radio.
void EmitRadioMap(YAML::Emitter& out, const std::vector<PropagationParams>& radio) {
  const PropagationParams& r = radio.front();
  out << YAML::BeginMap;
  out << YAML::Key << "propagation" << YAML::Value << Name(ToString(r.kind));
  if (r.kind == PropagationKind::kRange) {
    out << YAML::Key << "range" << YAML::Value;
    EmitList(out, radio, [](const PropagationParams& x) { return FormatMeters(x.range_m); });
  } else {
    const LogDistanceParams& l = r.log_distance;
    out << YAML::Key << "log_distance" << YAML::Value << YAML::Flow << YAML::BeginMap
        << YAML::Key << "exponent" << YAML::Value << Num(l.exponent)
        << YAML::Key << "reference_distance" << YAML::Value << FormatMeters(l.reference_distance_m)
        << YAML::Key << "reference_loss_db" << YAML::Value << Num(l.reference_loss_db)
        << YAML::Key << "tx_power_dbm" << YAML::Value << Num(l.tx_power_dbm)
        << YAML::Key << "sensitivity_dbm" << YAML::Value << Num(l.sensitivity_dbm)
        << YAML::Key << "shadowing_db" << YAML::Value << Num(l.shadowing_db)
        << YAML::Key << "shadowing_window" << YAML::Value
        << FormatDuration(SimTime::Seconds(l.shadowing_window_s)) << YAML::EndMap;
  }
  out << YAML::EndMap;
}

// network.radio: one map when every entry is a range radio (or there is one entry), else a list
// of maps, one per entry, which reads back to the same entries in the same order.
void EmitRadio(YAML::Emitter& out, const std::vector<PropagationParams>& radio) {
  out << YAML::Key << "radio" << YAML::Value;
  const bool all_ranges = std::all_of(radio.begin(), radio.end(),
                                      [](const PropagationParams& r) { return r.kind == PropagationKind::kRange; });
  if (all_ranges || radio.size() == 1) {
    EmitRadioMap(out, radio);
    return;
  }
  out << YAML::BeginSeq;
  for (const PropagationParams& r : radio) EmitRadioMap(out, {r});
  out << YAML::EndSeq;
}

void EmitNetwork(YAML::Emitter& out, const NetworkConfig& n) {
  out << YAML::Key << "network" << YAML::Value << YAML::BeginMap;
  out << YAML::Key << "model" << YAML::Value;
  EmitList(out, n.model, [](LinkModelKind m) { return Name(ToString(m)); });
  out << YAML::Key << "bandwidth" << YAML::Value;
  EmitList(out, n.bandwidth, [](DataRate r) { return ToString(r); });
  out << YAML::Key << "latency" << YAML::Value;
  EmitList(out, n.latency, [](SimTime t) { return FormatDuration(t); });
  out << YAML::Key << "queue_packets" << YAML::Value;
  EmitList(out, n.queue_packets, [](int q) { return q; });
  out << YAML::Key << "mtu" << YAML::Value;
  EmitList(out, n.mtu, [](Bytes b) { return b.value(); });
  out << YAML::Key << "loss" << YAML::Value;
  EmitLoss(out, n.loss);
  out << YAML::Key << "links" << YAML::Value << YAML::BeginSeq;
  for (const auto& l : n.links) {
    out << YAML::Flow << YAML::BeginMap << YAML::Key << "src" << YAML::Value << l.src.value
        << YAML::Key << "dst" << YAML::Value << l.dst.value;
    if (l.bandwidth) out << YAML::Key << "bandwidth" << YAML::Value << ToString(*l.bandwidth);
    if (l.latency) out << YAML::Key << "latency" << YAML::Value << FormatDuration(*l.latency);
    if (l.loss) {
      out << YAML::Key << "loss" << YAML::Value;
      EmitLoss(out, *l.loss);
    }
    out << YAML::EndMap;
  }
  out << YAML::EndSeq;
  // Only a radio config has the section (and only a routed one the routing), so every other
  // config's emitted form stays as it was.
  // wifi's propagation is the full mesh or the radio's (NetworkConfig): "radio" when over positions.
  const bool wifi = std::find(n.model.begin(), n.model.end(), LinkModelKind::kWifi) != n.model.end();
  const bool wifi_over_radio = wifi && PropagationsOf(n, LinkModelKind::kWifi).front().NeedsPositions();
  if (std::find(n.model.begin(), n.model.end(), LinkModelKind::kRadio) != n.model.end() || wifi_over_radio) {
    EmitRadio(out, n.radio);
  }
  if (wifi) {
    out << YAML::Key << "wifi" << YAML::Value << YAML::Flow << YAML::BeginMap << YAML::Key << "rate" << YAML::Value
        << ToString(n.wifi.rate) << YAML::Key << "basic_rate" << YAML::Value << ToString(n.wifi.basic_rate)
        << YAML::Key << "propagation" << YAML::Value << (wifi_over_radio ? "radio" : "full_mesh") << YAML::EndMap;
  }
  if (n.routing != std::vector<NextHopEntry>{NextHopEntry{}}) {
    out << YAML::Key << "routing" << YAML::Value << YAML::Flow << YAML::BeginSeq;
    for (const NextHopEntry& e : n.routing) {
      if (e.kind == NextHopKind::kLinkState && e.link_state != LinkStateParams{}) {
        out << YAML::BeginMap << YAML::Key << "kind" << YAML::Value << Name(ToString(e.kind))
            << YAML::Key << "hello" << YAML::Value << FormatDuration(e.link_state.hello)
            << YAML::Key << "topology" << YAML::Value << FormatDuration(e.link_state.topology) << YAML::EndMap;
      } else {
        out << Name(ToString(e.kind));
      }
    }
    out << YAML::EndSeq;
  }
  if (n.disconnected.kind != DisconnectedKind::kDrop) {
    out << YAML::Key << "disconnected" << YAML::Value << YAML::Flow << YAML::BeginMap
        << YAML::Key << "kind" << YAML::Value << Name(ToString(n.disconnected.kind))
        << YAML::Key << "hold_bytes" << YAML::Value << ToString(n.disconnected.hold_bytes)
        << YAML::Key << "hold_time" << YAML::Value << FormatDuration(n.disconnected.hold_time) << YAML::EndMap;
  }
  if (n.schedule) out << YAML::Key << "schedule" << YAML::Value << n.schedule->string();
  out << YAML::EndMap;
}

void EmitRest(YAML::Emitter& out, const ExperimentConfig& c) {
  const VerificationParams& v = c.agent.verification;
  out << YAML::Key << "verification" << YAML::Value << YAML::Flow << YAML::BeginMap
      << YAML::Key << "request_bytes" << YAML::Value << v.request_bytes.value()
      << YAML::Key << "max_distance" << YAML::Value << Num(v.max_distance);
  // Written only where it can matter or was changed: configs without bow_ strategies (the
  // default experiment's, the golden files') keep their text.
  const bool bow = std::any_of(c.sweep.strategies.begin(), c.sweep.strategies.end(),
                               [](const StrategySpec& s) { return s.bag_of_words(); });
  if (bow || v.bow_max_distance != VerificationParams{}.bow_max_distance) {
    out << YAML::Key << "bow_max_distance" << YAML::Value << Num(v.bow_max_distance);
  }
  out << YAML::EndMap;
  const ServiceParams& s = c.agent.service;
  out << YAML::Key << "service" << YAML::Value << YAML::Flow << YAML::BeginMap
      << YAML::Key << "fixed" << YAML::Value << FormatDuration(s.fixed)
      << YAML::Key << "per_comparison" << YAML::Value << FormatDuration(s.per_comparison)
      << YAML::EndMap;
  out << YAML::Key << "dropout" << YAML::Value << YAML::BeginSeq;
  for (const auto& d : c.dropout) {
    out << YAML::Flow << YAML::BeginMap << YAML::Key << "robot" << YAML::Value << d.robot
        << YAML::Key << "at" << YAML::Value << FormatDuration(d.at) << YAML::EndMap;
  }
  out << YAML::EndSeq;
  // Written only when it differs from the default, so the files of runs without failover stay
  // as they were before it existed; reading it back gives the same config either way.
  if (c.failover != FailoverParams{}) {
    out << YAML::Key << "failover" << YAML::Value << YAML::Flow << YAML::BeginMap
        << YAML::Key << "enabled" << YAML::Value << c.failover.enabled
        << YAML::Key << "heartbeat_period" << YAML::Value << FormatDuration(c.failover.heartbeat_period)
        << YAML::Key << "timeout" << YAML::Value << FormatDuration(c.failover.timeout) << YAML::EndMap;
  }
  const auto& o = c.outputs;
  out << YAML::Key << "outputs" << YAML::Value << YAML::Flow << YAML::BeginMap
      << YAML::Key << "figures" << YAML::Value << o.figures
      << YAML::Key << "queries" << YAML::Value << o.queries
      << YAML::Key << "messages" << YAML::Value << o.messages
      << YAML::Key << "lcm_log" << YAML::Value << o.lcm_log;
  // Only when on, so the config.yaml of every other run stays as it was before the key existed.
  if (o.connectivity) out << YAML::Key << "connectivity" << YAML::Value << true;
  if (o.pr_robots) out << YAML::Key << "pr_robots" << YAML::Value << *o.pr_robots;
  out << YAML::EndMap;
}

}  // namespace

std::string EmitConfig(const ExperimentConfig& c) {
  YAML::Emitter out;
  out.SetBoolFormat(YAML::TrueFalseBool);
  out << YAML::Comment("dvpr resolved config: every key, absolute paths. Run it again with "
                       "`dvpr run config.yaml`.");
  out << YAML::BeginMap;
  out << YAML::Key << "name" << YAML::Value << c.name;
  out << YAML::Key << "seed" << YAML::Value << c.seed;
  out << YAML::Key << "start_time" << YAML::Value << FormatUtcInstant(c.start_utime);
  EmitDataset(out, c.dataset);
  EmitTraining(out, c.training);
  EmitSweep(out, c.sweep);
  out << YAML::Key << "evaluation" << YAML::Value << YAML::Flow << YAML::BeginMap
      << YAML::Key << "gt_radius_m" << YAML::Value << Num(c.evaluation.radius_m)
      << YAML::Key << "suppression_frames" << YAML::Value << c.evaluation.suppression_frames
      << YAML::EndMap;
  EmitNetwork(out, c.network);
  EmitRest(out, c);
  out << YAML::EndMap;
  return std::string(out.c_str()) + "\n";
}

}  // namespace dvpr
