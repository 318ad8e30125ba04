#pragma once
// Virtual time: a signed count of nanoseconds. Never read from the wall clock.
#include <cmath>
#include <compare>
#include <cstdint>
#include <limits>
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

}  // namespace dvpr
