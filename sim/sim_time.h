#pragma once
// Virtual time: a signed count of nanoseconds. Never read from the wall clock.
//
// The operators do not check for overflow: they run on the simulator's hot path. Values that come
// from users are kept in ranges that cannot overflow when the config is validated (docs/config.md);
// where user values are combined before that, the Checked* functions below say whether the result
// is representable.
#include <cmath>
#include <compare>
#include <cstdint>
#include <limits>
#include <optional>
#include <ostream>

namespace dvpr {

class SimTime {
 public:
  constexpr SimTime() = default;

  static constexpr SimTime Nanos(std::int64_t ns) { return SimTime(ns); }
  static constexpr SimTime Micros(std::int64_t us) { return SimTime(us * 1000); }
  static constexpr SimTime Millis(std::int64_t ms) { return SimTime(ms * 1000000); }
  // Rounds to the nearest nanosecond.
  static SimTime Seconds(double s) { return SimTime(std::llround(s * 1e9)); }
  static constexpr SimTime Zero() { return SimTime(0); }
  static constexpr SimTime Max() { return SimTime(std::numeric_limits<std::int64_t>::max()); }

  constexpr std::int64_t ns() const { return ns_; }
  constexpr std::int64_t us() const { return ns_ / 1000; }  // truncates: LCM utime
  double ToSeconds() const { return static_cast<double>(ns_) * 1e-9; }
  double ToMillis() const { return static_cast<double>(ns_) * 1e-6; }

  constexpr auto operator<=>(const SimTime&) const = default;
  constexpr SimTime operator+(SimTime o) const { return SimTime(ns_ + o.ns_); }
  constexpr SimTime operator-(SimTime o) const { return SimTime(ns_ - o.ns_); }
  constexpr SimTime& operator+=(SimTime o) { ns_ += o.ns_; return *this; }
  constexpr SimTime& operator-=(SimTime o) { ns_ -= o.ns_; return *this; }
  constexpr SimTime operator*(std::int64_t k) const { return SimTime(ns_ * k); }

 private:
  constexpr explicit SimTime(std::int64_t ns) : ns_(ns) {}
  std::int64_t ns_ = 0;
};

inline std::ostream& operator<<(std::ostream& os, SimTime t) { return os << t.ns() << "ns"; }

// a + b, or nothing when it does not fit in int64 nanoseconds.
constexpr std::optional<SimTime> CheckedAdd(SimTime a, SimTime b) {
  std::int64_t ns = 0;
  if (__builtin_add_overflow(a.ns(), b.ns(), &ns)) return std::nullopt;
  return SimTime::Nanos(ns);
}

// t x k, or nothing when it does not fit.
constexpr std::optional<SimTime> CheckedMul(SimTime t, std::int64_t k) {
  std::int64_t ns = 0;
  if (__builtin_mul_overflow(t.ns(), k, &ns)) return std::nullopt;
  return SimTime::Nanos(ns);
}

// SimTime::Seconds(s), or nothing when s is not finite or s x 1e9 does not fit (llround of such a
// value is unspecified).
inline std::optional<SimTime> CheckedSeconds(double s) {
  const double ns = std::round(s * 1e9);
  // 2^63 is exactly representable; every double below it converts to int64 without overflow.
  if (!(ns >= -9223372036854775808.0 && ns < 9223372036854775808.0)) return std::nullopt;
  return SimTime::Nanos(static_cast<std::int64_t>(ns));
}

}  // namespace dvpr
