#pragma once
// Bytes read from a user's file, made fit for a one-line error message: a malformed header or
// token may hold newlines, control bytes or binary data, which would otherwise break the
// message over several lines or garble the terminal.
#include <cstddef>
#include <string>
#include <string_view>

namespace dvpr {

// `bytes` with printable ASCII kept, "\n", "\r", "\t" and "\\" escaped as in C, every other byte
// as "\xNN"; cut after `max_bytes` input bytes, marked by "...".
inline std::string Printable(std::string_view bytes, std::size_t max_bytes = 80) {
  static constexpr char kHex[] = "0123456789abcdef";
  std::string out;
  const std::size_t n = bytes.size() < max_bytes ? bytes.size() : max_bytes;
  for (std::size_t i = 0; i < n; ++i) {
    const auto c = static_cast<unsigned char>(bytes[i]);
    switch (c) {
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\t': out += "\\t"; break;
      case '\\': out += "\\\\"; break;
      default:
        if (c >= 0x20 && c < 0x7f) {
          out.push_back(static_cast<char>(c));
        } else {
          out += "\\x";
          out.push_back(kHex[c >> 4]);
          out.push_back(kHex[c & 0xf]);
        }
    }
  }
  if (n < bytes.size()) out += "...";
  return out;
}

}  // namespace dvpr
