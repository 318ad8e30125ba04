#pragma once
// Who hears whom (docs/network_model.md, "Propagation"): the full mesh (everyone hears everyone,
// no positions), or a propagation over the robots' positions (range, log_distance) with its
// numbers. A medium that has a propagation (radio, and wifi over the radio's; config:
// network.radio, network.wifi.propagation) is given one; the others are on the full mesh.
// Distances are metres on the ground plane of the trajectory's frame (KITTI's x and z: y points
// down).
//
// The log-distance defaults are ns-3's LogDistancePropagationLossModel (exponent 3, 46.6777 dB
// at 1 m: free space at 5.15 GHz) with ns-3's default transmit power for Wi-Fi (16.0206 dBm,
// 40 mW) and a receiver sensitivity of -82 dBm (802.11a's minimum for 6 Mbit/s); with them a
// transmission is heard up to 10^((16.0206 - 46.6777 + 82) / 30) = 51.5 m.
#include <string_view>

namespace dvpr {

// A propagation model by its config name: "full_mesh", "range", "log_distance", or one a
// program registered (propagation_registry.h). The name's characters must outlive every kind made
// from it (a string literal).
class PropagationKind {
 public:
  static const PropagationKind kFullMesh;
  static const PropagationKind kRange;
  static const PropagationKind kLogDistance;

  constexpr explicit PropagationKind(std::string_view name) : name_(name) {}
  constexpr std::string_view name() const { return name_; }
  friend constexpr bool operator==(PropagationKind a, PropagationKind b) { return a.name_ == b.name_; }

 private:
  std::string_view name_;
};
inline constexpr PropagationKind PropagationKind::kFullMesh{"full_mesh"};
inline constexpr PropagationKind PropagationKind::kRange{"range"};
inline constexpr PropagationKind PropagationKind::kLogDistance{"log_distance"};

// A registered model's kind by name (propagation_registry.h; "full_mesh" only when
// `with_full_mesh`: a radio's propagation is over positions); throws std::invalid_argument
// "unknown value '<name>' (expected one of: range, log_distance)".
PropagationKind ParsePropagationKind(std::string_view name, bool with_full_mesh = false);
inline std::string_view ToString(PropagationKind kind) { return kind.name(); }

struct LogDistanceParams {
  double exponent = 3.0;
  double reference_distance_m = 1.0;
  double reference_loss_db = 46.6777;
  double tx_power_dbm = 16.0206;
  double sensitivity_dbm = -82.0;
  // Standard deviation of log-normal shadowing (dB; 0: none). One draw per unordered pair and
  // window of shadowing_window_s seconds, from the run's seeded stream, so both directions of a
  // pair and every transmission in a window see the same value and runs stay deterministic.
  double shadowing_db = 0.0;
  double shadowing_window_s = 1.0;

  // The largest distance at which a transmission is heard without shadowing (metres).
  double MeanRangeM() const;
  // Throws std::invalid_argument "<field>: ..." ("exponent: must be in [1, 10], got 0.5").
  void Validate() const;
  bool operator==(const LogDistanceParams&) const = default;
};

struct PropagationParams {
  static constexpr double kMaxRangeM = 1e9;  // the pose loader's range: farther says nothing more

  PropagationKind kind = PropagationKind::kFullMesh;
  double range_m = 200.0;  // range: heard iff the ground-plane distance is at most this
  LogDistanceParams log_distance = {};

  // A radio's propagation when none is given: range 200 m.
  static PropagationParams Radio() { return PropagationParams{.kind = PropagationKind::kRange}; }
  // Who hears whom depends on where the robots are: a trajectory is needed (the registered
  // model's say; propagation_registry.h).
  bool NeedsPositions() const;
  // Throws std::invalid_argument "<field>: ..." ("range: must be in (0, 1e9] metres, got -3",
  // "log_distance.exponent: ...").
  void Validate() const;
  bool operator==(const PropagationParams&) const = default;
};

}  // namespace dvpr
