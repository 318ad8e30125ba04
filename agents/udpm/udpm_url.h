#pragma once
// An LCM provider URL for UDP multicast, read the way LCM reads it (lcm/lcm_udpm.c):
//
//   udpm://GROUP:PORT?ttl=T&recv_buf_size=B
//
// GROUP is an IPv4 multicast address (224.0.0.0/4) and PORT a port, both optional (LCM's
// 239.255.76.67 and 7667); ttl (0..255, default 0: the datagrams stay on this machine) and
// recv_buf_size (bytes asked of the kernel for the receive buffer) are the only options. Any
// other provider (file://, memq://, tcpq://, ...) or option is refused: a team of processes
// needs the group, and a log file named by a URL must not be opened, let alone overwritten.
#include <cstdint>
#include <optional>
#include <string>

namespace dvpr::udpm {

inline constexpr const char* kLcmDefaultUrl = "udpm://239.255.76.67:7667?ttl=0";

struct Url {
  std::uint32_t group = 0;  // host byte order
  std::uint16_t port = 0;
  int ttl = 0;
  std::optional<int> recv_buf_size;
  std::string text;         // the URL as given (what liblcm is opened with for publishing)
};

// Parses `url`; empty means $LCM_DEFAULT_URL, else LCM's default. Throws std::invalid_argument
// naming the URL and what is wrong with it.
Url ParseUrl(const std::string& url);

}  // namespace dvpr::udpm
