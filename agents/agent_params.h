#pragma once
// What a robot's protocol is tuned by (docs/design.md sections 1 and 3): the matching window, what
// serving costs, geometric verification. The config holds these structs as they are (sections
// service and verification); each Validate() throws std::invalid_argument "<field>: <problem>",
// naming the field as the struct spells it.
#include <cfloat>

#include "net_models/core/units.h"
#include "sim/sim_time.h"

namespace dvpr {

// Per-robot load: serving a search takes fixed + per_comparison x descriptors compared; serving
// a verification request takes fixed.
struct ServiceParams {
  // The valid ranges (docs/config.md). A search compares at most every frame of the run (an int),
  // so its service time is below 24 h + 1 ms x 2^31 = 2.2e15 ns: far inside int64 nanoseconds.
  static constexpr SimTime kMaxFixed = SimTime::Millis(24LL * 3600 * 1000);  // 24 h
  static constexpr SimTime kMaxPerComparison = SimTime::Millis(1);

  SimTime fixed = SimTime::Micros(50);
  SimTime per_comparison = SimTime::Nanos(20);
  void Validate() const;
  bool operator==(const ServiceParams&) const = default;
};

// Step 4 of the method: a match this close is verified with the robot that saw the frame.
struct VerificationParams {
  // The request's size travels in an int32 field of verify_request_t (and the request holds that
  // many bytes): 1 GiB fits it with room for the message's header.
  static constexpr Bytes kMaxRequestBytes{std::int64_t{1} << 30};
  // max_distance is compared as a float.
  static constexpr double kMaxDistance = FLT_MAX;

  Bytes request_bytes{25000};  // payload of the request: keypoints + local descriptors stand-in
  // Verify a match at most this far (squared L2). Compared as float, as the distances are.
  double max_distance = 0.6;
  // The bag-of-words strategies' counterpart (agents/bow_robot_agent.h, docs/bow.md): verify a
  // voted match at most this far, the distance being 1 - the voters' summed L1 score, in [0, 1].
  double bow_max_distance = 0.95;
  void Validate() const;
  bool operator==(const VerificationParams&) const = default;
};

struct AgentParams {
  int suppression_frames = 250;  // never match a frame this close in the sequence
  ServiceParams service;
  VerificationParams verification;
  void Validate() const;  // names nested fields with their member: "service.fixed: ..."
  bool operator==(const AgentParams&) const = default;
};

}  // namespace dvpr
