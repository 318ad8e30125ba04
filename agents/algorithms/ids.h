#pragma once
// Strong identifiers: a robot and a frame are not interchangeable ints.
#include <compare>
#include <cstdint>
#include <functional>
#include <ostream>

namespace dvpr {

template <typename Tag, typename Rep>
struct StrongId {
  Rep value{};
  constexpr StrongId() = default;
  constexpr explicit StrongId(Rep v) : value(v) {}
  constexpr auto operator<=>(const StrongId&) const = default;
};

struct RobotTag {};
struct FrameTag {};
// A robot of the team, 0..n-1.
using RobotId = StrongId<RobotTag, std::int32_t>;
// A frame of the deployment sequence: its index in the full sequence (not in
// the robot's sub-sequence), so the suppression window applies across robots.
using FrameId = StrongId<FrameTag, std::int32_t>;

// The largest count an LCM message's int16 field holds (lcmtypes/dvpr/*.lcm): a robot id, a
// descriptor's dim, a centroid table's k.
inline constexpr int kMaxWireInt16 = 32767;

template <typename Tag, typename Rep>
std::ostream& operator<<(std::ostream& os, StrongId<Tag, Rep> id) { return os << id.value; }

}  // namespace dvpr

template <typename Tag, typename Rep>
struct std::hash<dvpr::StrongId<Tag, Rep>> {
  std::size_t operator()(dvpr::StrongId<Tag, Rep> id) const noexcept {
    return std::hash<Rep>{}(id.value);
  }
};
