#include "experiments/config/utc_instant.h"

#include <chrono>
#include <cstdio>

namespace dvpr {

namespace {

// The digits text[pos, pos + n) as a number; empty if any is not a digit.
std::optional<int> Digits(std::string_view text, std::size_t pos, std::size_t n) {
  int v = 0;
  for (std::size_t i = pos; i < pos + n; ++i) {
    if (i >= text.size() || text[i] < '0' || text[i] > '9') return std::nullopt;
    v = v * 10 + (text[i] - '0');
  }
  return v;
}

}  // namespace

std::optional<std::int64_t> ParseUtcInstant(std::string_view text) {
  using namespace std::chrono;
  // YYYY-MM-DDTHH:MM:SS: the separators at fixed places, then an optional fraction and Z.
  if (text.size() < 20 || text[4] != '-' || text[7] != '-' || text[10] != 'T' || text[13] != ':' ||
      text[16] != ':' || text.back() != 'Z') {
    return std::nullopt;
  }
  const auto y = Digits(text, 0, 4), mo = Digits(text, 5, 2), d = Digits(text, 8, 2);
  const auto h = Digits(text, 11, 2), mi = Digits(text, 14, 2), s = Digits(text, 17, 2);
  if (!y || !mo || !d || !h || !mi || !s || *h > 23 || *mi > 59 || *s > 59) return std::nullopt;
  const year_month_day date{year{*y}, month{static_cast<unsigned>(*mo)}, day{static_cast<unsigned>(*d)}};
  if (!date.ok() || *y < 1970) return std::nullopt;
  std::int64_t micros = 0;
  const std::size_t fraction = text.size() - 20;  // "." and the digits, or nothing
  if (fraction > 0) {
    if (text[19] != '.' || fraction < 2 || fraction > 7) return std::nullopt;
    const auto f = Digits(text, 20, fraction - 1);
    if (!f) return std::nullopt;
    micros = *f;
    for (std::size_t i = fraction - 1; i < 6; ++i) micros *= 10;
  }
  const auto at = sys_days(date) + hours(*h) + minutes(*mi) + seconds(*s);
  return duration_cast<microseconds>(at.time_since_epoch()).count() + micros;
}

std::string FormatUtcInstant(std::int64_t utime) {
  using namespace std::chrono;
  const sys_time<microseconds> t{microseconds(utime)};
  const auto days = floor<std::chrono::days>(t);
  const year_month_day date{days};
  const hh_mm_ss<microseconds> time{t - days};
  char buf[40];
  std::snprintf(buf, sizeof buf, "%04d-%02u-%02uT%02d:%02d:%02d", static_cast<int>(date.year()),
                static_cast<unsigned>(date.month()), static_cast<unsigned>(date.day()),
                static_cast<int>(time.hours().count()), static_cast<int>(time.minutes().count()),
                static_cast<int>(time.seconds().count()));
  std::string out = buf;
  if (const auto us = time.subseconds().count(); us != 0) {
    std::snprintf(buf, sizeof buf, ".%06lld", static_cast<long long>(us));
    std::string fraction = buf;
    while (fraction.back() == '0') fraction.pop_back();
    out += fraction;
  }
  return out + "Z";
}

}  // namespace dvpr
