#pragma once
// The config's `start_time`: a UTC instant written as ISO 8601 ("2011-10-03T12:00:00Z", with up
// to six digits of fraction: "2011-10-03T12:00:00.25Z"), held as microseconds since the Unix
// epoch, the unit of LCM's utime. Only this one form: a time zone other than Z or a date without
// a time would each need rules of their own, and one form reads back unchanged.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace dvpr {

inline constexpr std::int64_t kMinUtcInstant = 0;                   // 1970-01-01T00:00:00Z
inline constexpr std::int64_t kMaxUtcInstant = 253402300799999999;  // 9999-12-31T23:59:59.999999Z

// Empty when `text` is not of the form YYYY-MM-DDTHH:MM:SS[.f{1,6}]Z, names no real date or time
// of day (2011-02-30, 24:00:00, a leap second) or lies before 1970.
std::optional<std::int64_t> ParseUtcInstant(std::string_view text);

// The form ParseUtcInstant reads; the fraction only when there is one, trailing zeros dropped.
// `utime` in [kMinUtcInstant, kMaxUtcInstant].
std::string FormatUtcInstant(std::int64_t utime);

}  // namespace dvpr
