#pragma once
// Network units as types (ns-3 DataRate): a byte count and a data rate are not
// interchangeable integers, and transmission time is computed exactly.
//
// Parsing accepts a decimal number followed by a unit ("10Mbps", "1.5KiB",
// "5ms"; one optional space between) and rejects a value without a unit or
// with an unknown one by throwing std::invalid_argument that quotes the value
// and lists the accepted units. Numbers are parsed as exact decimals (no
// floating point), so "1.5Gbps" is exactly 1'500'000'000 bit/s on every
// platform; a result that is not a whole number of the base unit (bit/s, ns,
// byte) is rounded to the nearest, halves away from zero. A well-formed value too large for an
// int64 count of the base unit throws QuantityTooLarge (an std::invalid_argument), so a caller
// can report its own range; no input overflows the arithmetic of the parser.
#include <compare>
#include <cstdint>
#include <ostream>
#include <stdexcept>
#include <string>
#include <string_view>

#include "sim/sim_time.h"

namespace dvpr {

// A number with a known unit that does not fit an int64 count of bit/s, ns or bytes.
class QuantityTooLarge : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// A count of bytes (octets).
class Bytes {
 public:
  constexpr Bytes() = default;
  constexpr explicit Bytes(std::int64_t n) : n_(n) {}
  constexpr std::int64_t value() const { return n_; }

  constexpr auto operator<=>(const Bytes&) const = default;
  constexpr Bytes operator+(Bytes o) const { return Bytes(n_ + o.n_); }
  constexpr Bytes operator-(Bytes o) const { return Bytes(n_ - o.n_); }
  constexpr Bytes& operator+=(Bytes o) { n_ += o.n_; return *this; }
  constexpr Bytes& operator-=(Bytes o) { n_ -= o.n_; return *this; }
  constexpr Bytes operator*(std::int64_t k) const { return Bytes(n_ * k); }

 private:
  std::int64_t n_ = 0;
};

// A data rate in bits per second.
class DataRate {
 public:
  constexpr DataRate() = default;
  static constexpr DataRate BitsPerSecond(std::int64_t bps) { return DataRate(bps); }
  static constexpr DataRate Kbps(std::int64_t k) { return DataRate(k * 1000); }
  static constexpr DataRate Mbps(std::int64_t m) { return DataRate(m * 1000000); }
  static constexpr DataRate Gbps(std::int64_t g) { return DataRate(g * 1000000000); }

  constexpr std::int64_t bps() const { return bps_; }
  constexpr auto operator<=>(const DataRate&) const = default;

  // Time to put n bytes on a link at this rate: n * 8 / rate, rounded UP to
  // the next nanosecond (a frame is not sent until its last bit is), in exact
  // integer arithmetic. Requires bps() > 0.
  SimTime TxTime(Bytes n) const;

 private:
  constexpr explicit DataRate(std::int64_t bps) : bps_(bps) {}
  std::int64_t bps_ = 0;
};

// "10Mbps", "54Mbit/s", "1.5Gbps", "800kbps", "100 kbit/s", "2MBps" (bytes/s).
// Bit units: bps, b/s, bit/s; byte units: Bps, B/s. SI prefixes k/K, M, G, T
// (x1000) and binary Ki, Mi, Gi, Ti (x1024). Negative values are rejected.
DataRate ParseDataRate(std::string_view text);
// "5ms", "50us" (or "µs"), "20ns", "1.5s", "2min", "1h". Negative values are rejected.
SimTime ParseDuration(std::string_view text);
// "1500B", "25kB", "1.5KiB", "64KiB", "2MB", "1MiB", "1GB", "1GiB".
// SI kB/MB/GB (x1000), IEC KiB/MiB/GiB (x1024). "KB" is rejected as ambiguous.
Bytes ParseBytes(std::string_view text);

// A length in metres, whole millimetres: "200m", "1.5km", "250 m", "30cm", "5mm". Negative
// values are rejected.
double ParseMeters(std::string_view text);
// A length for ParseMeters, in the largest unit that keeps it whole: "200m", "1.5km" is
// "1500m", "0.5m" is "500mm".
std::string FormatMeters(double metres);

// Human-readable forms, in the largest unit that keeps the value whole
// ("10Mbps", "1500B", "64KiB"); they parse back to the same value.
std::string ToString(DataRate rate);
std::string ToString(Bytes bytes);
// A duration the same way, for ParseDuration: "2ms", "50us", "20ns", "12s", "2min".
std::string FormatDuration(SimTime t);

inline std::ostream& operator<<(std::ostream& os, Bytes b) { return os << ToString(b); }
inline std::ostream& operator<<(std::ostream& os, DataRate r) { return os << ToString(r); }

}  // namespace dvpr
