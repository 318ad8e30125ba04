#include "net_models/core/units.h"

#include <array>
#include <cctype>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>

namespace dvpr {
namespace {

// __extension__: __int128 is a GCC/Clang extension; it keeps rate x time products exact.
__extension__ typedef __int128 Wide;

struct UnitEntry {
  std::string_view name;
  std::int64_t factor;  // base units (bit/s, ns, byte) per unit
};

// An exact non-negative decimal: mantissa / 10^frac_digits.
struct Decimal {
  Wide mantissa = 0;
  int frac_digits = 0;
  int int_digits = 0;  // significant digits before the point (leading zeros not counted)
};

std::string_view Trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

// Parses "123", "1.5", ".5" at the start of s; advances s past the number. `too_long` is set when
// the digits do not fit an exact __int128 mantissa (about 38 significant digits).
std::optional<Decimal> ParseDecimal(std::string_view& s, bool& too_long) {
  Decimal d;
  too_long = false;
  bool any_digit = false;
  bool in_fraction = false;
  std::size_t i = 0;
  for (; i < s.size(); ++i) {
    const char c = s[i];
    if (c == '.' && !in_fraction) {
      in_fraction = true;
      continue;
    }
    if (c < '0' || c > '9') break;
    any_digit = true;
    if (!in_fraction && (d.int_digits > 0 || c != '0')) ++d.int_digits;
    if (__builtin_mul_overflow(d.mantissa, 10, &d.mantissa) ||
        __builtin_add_overflow(d.mantissa, c - '0', &d.mantissa)) {
      too_long = true;
    }
    if (in_fraction) ++d.frac_digits;
  }
  if (!any_digit) return std::nullopt;
  s.remove_prefix(i);
  return d;
}

[[noreturn]] void Fail(std::string_view what, std::string_view text, std::string_view expected) {
  throw std::invalid_argument("invalid " + std::string(what) + " \"" + std::string(text) +
                              "\": expected " + std::string(expected));
}

[[noreturn]] void FailTooLarge(std::string_view what, std::string_view text, std::string_view base) {
  throw QuantityTooLarge("invalid " + std::string(what) + " \"" + std::string(text) +
                         "\": expected at most " +
                         std::to_string(std::numeric_limits<std::int64_t>::max()) + std::string(base));
}

// mantissa / 10^frac_digits x factor in base units, rounded half up; nothing when an
// intermediate or the result does not fit.
std::optional<std::int64_t> ToBaseUnits(const Decimal& number, std::int64_t factor) {
  Wide scale = 1;
  for (int i = 0; i < number.frac_digits; ++i) {
    if (__builtin_mul_overflow(scale, 10, &scale)) return std::nullopt;
  }
  Wide twice = 0;
  Wide twice_scale = 0;
  Wide rounded = 0;
  if (__builtin_mul_overflow(number.mantissa, static_cast<Wide>(factor) * 2, &twice) ||
      __builtin_mul_overflow(scale, 2, &twice_scale) || __builtin_add_overflow(twice, scale, &rounded)) {
    return std::nullopt;
  }
  const Wide value = rounded / twice_scale;
  if (value > std::numeric_limits<std::int64_t>::max()) return std::nullopt;
  return static_cast<std::int64_t>(value);
}

// number [space] unit -> value in base units, rounded half up.
template <std::size_t N>
std::int64_t ParseQuantity(std::string_view text, std::string_view what, const std::array<UnitEntry, N>& units,
                           std::string_view expected, std::string_view base) {
  std::string_view rest = Trim(text);
  if (!rest.empty() && rest.front() == '-') Fail(what, text, "a non-negative value; " + std::string(expected));
  if (!rest.empty() && rest.front() == '+') rest.remove_prefix(1);
  bool too_long = false;
  const auto number = ParseDecimal(rest, too_long);
  if (!number) Fail(what, text, expected);
  // "1e6bps": the number is exact decimal digits only, so an exponent is named rather than
  // reported as the unknown unit "e6bps".
  if (rest.size() >= 2 && (rest[0] == 'e' || rest[0] == 'E') &&
      (std::isdigit(static_cast<unsigned char>(rest[1])) || rest[1] == '-' || rest[1] == '+')) {
    Fail(what, text, "digits without an exponent (e.g. 0.001 or 1000, not 1e-3 or 1e3); " + std::string(expected));
  }
  if (!rest.empty() && rest.front() == ' ') rest.remove_prefix(1);
  if (rest.empty()) Fail(what, text, "a unit after the number; " + std::string(expected));
  for (const UnitEntry& u : units) {
    if (u.name != rest) continue;
    // 20 integer digits are at least 1e19 base units, beyond int64; a longer fraction is refused
    // rather than rounded, as it cannot be held exactly.
    if (number->int_digits > 19) FailTooLarge(what, text, base);
    if (too_long) Fail(what, text, "at most 38 significant digits");
    const auto value = ToBaseUnits(*number, u.factor);
    if (!value) FailTooLarge(what, text, base);
    return *value;
  }
  Fail(what, text, "a known unit; " + std::string(expected));
}

constexpr std::int64_t kKi = 1024;

// Prefix x suffix, spelled out so the accepted set is visible in one place.
constexpr std::array<UnitEntry, 50> kRateUnits = {{
    {"bps", 1}, {"b/s", 1}, {"bit/s", 1}, {"Bps", 8}, {"B/s", 8},
    {"kbps", 1000}, {"kb/s", 1000}, {"kbit/s", 1000}, {"kBps", 8000}, {"kB/s", 8000},
    {"Kbps", 1000}, {"Kb/s", 1000}, {"Kbit/s", 1000}, {"KBps", 8000}, {"KB/s", 8000},
    {"Mbps", 1000000}, {"Mb/s", 1000000}, {"Mbit/s", 1000000}, {"MBps", 8000000}, {"MB/s", 8000000},
    {"Gbps", 1000000000}, {"Gb/s", 1000000000}, {"Gbit/s", 1000000000},
    {"GBps", 8000000000}, {"GB/s", 8000000000},
    {"Tbps", 1000000000000}, {"Tb/s", 1000000000000}, {"Tbit/s", 1000000000000},
    {"TBps", 8000000000000}, {"TB/s", 8000000000000},
    {"Kibps", kKi}, {"Kib/s", kKi}, {"Kibit/s", kKi}, {"KiBps", 8 * kKi}, {"KiB/s", 8 * kKi},
    {"Mibps", kKi * kKi}, {"Mib/s", kKi * kKi}, {"Mibit/s", kKi * kKi},
    {"MiBps", 8 * kKi * kKi}, {"MiB/s", 8 * kKi * kKi},
    {"Gibps", kKi * kKi * kKi}, {"Gib/s", kKi * kKi * kKi}, {"Gibit/s", kKi * kKi * kKi},
    {"GiBps", 8 * kKi * kKi * kKi}, {"GiB/s", 8 * kKi * kKi * kKi},
    {"Tibps", kKi * kKi * kKi * kKi}, {"Tib/s", kKi * kKi * kKi * kKi},
    {"Tibit/s", kKi * kKi * kKi * kKi},
    {"TiBps", 8 * kKi * kKi * kKi * kKi}, {"TiB/s", 8 * kKi * kKi * kKi * kKi},
}};

constexpr std::array<UnitEntry, 7> kDurationUnits = {{
    {"ns", 1}, {"us", 1000}, {"\xC2\xB5s", 1000}, {"ms", 1000000}, {"s", 1000000000},
    {"min", 60'000'000'000}, {"h", 3'600'000'000'000},
}};

constexpr std::array<UnitEntry, 4> kLengthUnits = {{{"mm", 1}, {"cm", 10}, {"m", 1000}, {"km", 1000000}}};

constexpr std::array<UnitEntry, 7> kByteUnits = {{
    {"B", 1}, {"kB", 1000}, {"MB", 1000000}, {"GB", 1000000000},
    {"KiB", kKi}, {"MiB", kKi * kKi}, {"GiB", kKi * kKi * kKi},
}};

}  // namespace

SimTime DataRate::TxTime(Bytes n) const {
  if (bps_ <= 0) throw std::domain_error("DataRate::TxTime on a non-positive rate");
  // Every message's frames come here: up to 2^30 bytes the 64-bit division gives the same
  // quotient as the 128-bit one below (n x 8e9 + bps < 2^64), at a fraction of its cost.
  if (n.value() >= 0 && n.value() <= (std::int64_t{1} << 30)) {
    const auto bits_ns = static_cast<std::uint64_t>(n.value()) * 8 * 1000000000;
    const auto bps = static_cast<std::uint64_t>(bps_);
    return SimTime::Nanos(static_cast<std::int64_t>((bits_ns + bps - 1) / bps));
  }
  // |n| < 2^63, so n x 8e9 < 2^96 fits; only the result may exceed int64.
  const Wide bits_ns = static_cast<Wide>(n.value()) * 8 * 1000000000;
  const Wide ns = (bits_ns + bps_ - 1) / bps_;
  if (ns > std::numeric_limits<std::int64_t>::max()) {
    throw std::domain_error("DataRate::TxTime: " + std::to_string(n.value()) + " bytes at " +
                            std::to_string(bps_) + "bps take longer than the largest SimTime");
  }
  return SimTime::Nanos(static_cast<std::int64_t>(ns));
}

DataRate ParseDataRate(std::string_view text) {
  return DataRate::BitsPerSecond(ParseQuantity(
      text, "data rate", kRateUnits,
      "a number and a rate unit such as bps, kbps, Mbps, Gbps, Mbit/s, MBps or MiB/s (e.g. \"10Mbps\")",
      "bps"));
}

SimTime ParseDuration(std::string_view text) {
  return SimTime::Nanos(ParseQuantity(text, "duration", kDurationUnits,
                                      "a number and a time unit: ns, us, ms, s, min or h (e.g. \"5ms\")",
                                      "ns"));
}

Bytes ParseBytes(std::string_view text) {
  return Bytes(ParseQuantity(text, "byte size", kByteUnits,
                             "a number and a size unit: B, kB, MB, GB, KiB, MiB or GiB (e.g. \"64KiB\")",
                             "B"));
}

double ParseMeters(std::string_view text) {
  const std::int64_t mm = ParseQuantity(text, "length", kLengthUnits,
                                        "a number and a length unit: mm, cm, m or km (e.g. \"200m\")", "mm");
  return static_cast<double>(mm) / 1000.0;
}

std::string FormatMeters(double metres) {
  const auto mm = static_cast<std::int64_t>(std::llround(metres * 1000.0));
  if (mm != 0 && mm % 1000 == 0) return std::to_string(mm / 1000) + "m";
  return std::to_string(mm) + "mm";
}

std::string ToString(DataRate rate) {
  constexpr std::array<UnitEntry, 3> kLargest = {{{"Gbps", 1000000000}, {"Mbps", 1000000}, {"kbps", 1000}}};
  for (const UnitEntry& u : kLargest) {
    if (rate.bps() != 0 && rate.bps() % u.factor == 0) {
      return std::to_string(rate.bps() / u.factor) + std::string(u.name);
    }
  }
  return std::to_string(rate.bps()) + "bps";
}

std::string ToString(Bytes bytes) {
  constexpr std::array<UnitEntry, 6> kLargest = {{{"GiB", kKi * kKi * kKi}, {"MiB", kKi * kKi}, {"KiB", kKi},
                                                 {"GB", 1000000000}, {"MB", 1000000}, {"kB", 1000}}};
  for (const UnitEntry& u : kLargest) {
    if (bytes.value() != 0 && bytes.value() % u.factor == 0) {
      return std::to_string(bytes.value() / u.factor) + std::string(u.name);
    }
  }
  return std::to_string(bytes.value()) + "B";
}

std::string FormatDuration(SimTime t) {
  const std::int64_t ns = t.ns();
  for (const UnitEntry& u : {UnitEntry{"h", 3'600'000'000'000}, UnitEntry{"min", 60'000'000'000},
                             UnitEntry{"s", 1'000'000'000}, UnitEntry{"ms", 1'000'000}, UnitEntry{"us", 1'000}}) {
    if (ns != 0 && ns % u.factor == 0) return std::to_string(ns / u.factor) + std::string(u.name);
  }
  return std::to_string(ns) + "ns";
}

}  // namespace dvpr
