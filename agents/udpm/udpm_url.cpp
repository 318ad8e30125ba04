#include "agents/udpm/udpm_url.h"

#include <arpa/inet.h>

#include <charconv>
#include <cstdlib>
#include <stdexcept>
#include <string_view>

namespace dvpr::udpm {

namespace {

[[noreturn]] void Fail(const std::string& url, const std::string& what) {
  throw std::invalid_argument("LCM URL '" + url + "': " + what);
}

// A decimal integer in [low, high], the whole of `text`.
std::optional<long> Integer(std::string_view text, long low, long high) {
  long v = 0;
  const auto r = std::from_chars(text.data(), text.data() + text.size(), v);
  if (text.empty() || r.ec != std::errc() || r.ptr != text.data() + text.size() || v < low || v > high) {
    return std::nullopt;
  }
  return v;
}

void ReadOption(const std::string& url, std::string_view option, Url& u) {
  const auto eq = option.find('=');
  const std::string_view key = option.substr(0, eq);
  const std::string_view value = eq == std::string_view::npos ? std::string_view() : option.substr(eq + 1);
  if (key == "ttl") {
    const auto v = Integer(value, 0, 255);
    if (!v) Fail(url, "ttl must be an integer in [0, 255], got '" + std::string(value) + "'");
    u.ttl = static_cast<int>(*v);
  } else if (key == "recv_buf_size") {
    const auto v = Integer(value, 1, 0x7fffffff);
    if (!v) Fail(url, "recv_buf_size must be a number of bytes in [1, 2^31), got '" + std::string(value) + "'");
    u.recv_buf_size = static_cast<int>(*v);
  } else {
    Fail(url, "unknown option '" + std::string(key) + "' (udpm takes ttl and recv_buf_size)");
  }
}

}  // namespace

Url ParseUrl(const std::string& given) {
  std::string url = given;
  if (url.empty()) {
    const char* env = std::getenv("LCM_DEFAULT_URL");
    url = env != nullptr && *env != '\0' ? env : kLcmDefaultUrl;
  }
  const auto scheme_end = url.find("://");
  if (scheme_end == std::string::npos) Fail(url, "expected udpm://GROUP:PORT?options");
  const std::string provider = url.substr(0, scheme_end);
  if (provider != "udpm") {
    Fail(url, "only the udpm provider (UDP multicast) connects a team of processes, got '" + provider + "'");
  }
  Url u;
  u.text = url;
  const std::string_view rest = std::string_view(url).substr(scheme_end + 3);
  const auto query = rest.find('?');
  const std::string_view network = rest.substr(0, query);
  std::string group = "239.255.76.67";
  u.port = 7667;
  if (!network.empty()) {
    const auto colon = network.find(':');
    group = std::string(network.substr(0, colon));
    if (colon != std::string_view::npos) {
      const auto port = Integer(network.substr(colon + 1), 1, 65535);
      if (!port) Fail(url, "the port must be an integer in [1, 65535], got '" + std::string(network.substr(colon + 1)) + "'");
      u.port = static_cast<std::uint16_t>(*port);
    }
  }
  in_addr address{};
  if (inet_pton(AF_INET, group.c_str(), &address) != 1) Fail(url, "'" + group + "' is not an IPv4 address");
  u.group = ntohl(address.s_addr);
  if ((u.group >> 28) != 0xE) Fail(url, group + " is not a multicast address (224.0.0.0 to 239.255.255.255)");
  if (query != std::string_view::npos) {
    std::string_view options = rest.substr(query + 1);
    while (!options.empty()) {
      const auto amp = options.find('&');
      ReadOption(url, options.substr(0, amp), u);
      options = amp == std::string_view::npos ? std::string_view() : options.substr(amp + 1);
    }
  }
  return u;
}

}  // namespace dvpr::udpm
