#include "agents/udpm/udpm_socket.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>

namespace dvpr::udpm {

namespace {

std::string Dotted(std::uint32_t host_order) {
  in_addr a{};
  a.s_addr = htonl(host_order);
  char text[INET_ADDRSTRLEN] = {};
  inet_ntop(AF_INET, &a, text, sizeof text);
  return text;
}

}  // namespace

Socket::Socket(const Url& url) {
  const std::string where = "LCM group " + Dotted(url.group) + ":" + std::to_string(url.port);
  auto fail = [&](const std::string& step) {
    const std::string why = std::strerror(errno);
    if (fd_ >= 0) close(fd_);
    fd_ = -1;
    throw std::runtime_error(where + ": " + step + ": " + why);
  };
  fd_ = socket(AF_INET, SOCK_DGRAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
  if (fd_ < 0) fail("cannot create a UDP socket");
  const int on = 1;
  if (setsockopt(fd_, SOL_SOCKET, SO_REUSEADDR, &on, sizeof on) != 0) fail("SO_REUSEADDR");
  if (setsockopt(fd_, SOL_SOCKET, SO_REUSEPORT, &on, sizeof on) != 0) fail("SO_REUSEPORT");
  if (setsockopt(fd_, SOL_SOCKET, SO_RXQ_OVFL, &on, sizeof on) != 0) fail("SO_RXQ_OVFL");
  if (url.recv_buf_size && setsockopt(fd_, SOL_SOCKET, SO_RCVBUF, &*url.recv_buf_size, sizeof(int)) != 0) {
    fail("SO_RCVBUF " + std::to_string(*url.recv_buf_size));
  }
  socklen_t length = sizeof receive_buffer_bytes_;
  getsockopt(fd_, SOL_SOCKET, SO_RCVBUF, &receive_buffer_bytes_, &length);
  ip_mreq membership{};
  membership.imr_multiaddr.s_addr = htonl(url.group);
  membership.imr_interface.s_addr = htonl(INADDR_ANY);
  if (setsockopt(fd_, IPPROTO_IP, IP_ADD_MEMBERSHIP, &membership, sizeof membership) != 0) {
    fail("cannot join the group (is there a multicast route? for this machine alone: ip link set lo "
         "multicast on; ip route add 224.0.0.0/4 dev lo; README, \"Running real agents\")");
  }
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(url.group);
  address.sin_port = htons(url.port);
  if (bind(fd_, reinterpret_cast<const sockaddr*>(&address), sizeof address) != 0) {
    fail("cannot bind (a program holds the port without SO_REUSEADDR?)");
  }
}

Socket::~Socket() {
  if (fd_ >= 0) close(fd_);
}

std::optional<Socket::Received> Socket::Receive(std::span<std::uint8_t> buffer) {
  sockaddr_in from{};
  iovec data{buffer.data(), buffer.size()};
  alignas(cmsghdr) char control[CMSG_SPACE(sizeof(std::uint32_t))];
  msghdr m{};
  m.msg_name = &from;
  m.msg_namelen = sizeof from;
  m.msg_iov = &data;
  m.msg_iovlen = 1;
  m.msg_control = control;
  m.msg_controllen = sizeof control;
  ssize_t n = -1;
  do {
    n = recvmsg(fd_, &m, MSG_DONTWAIT);
  } while (n < 0 && errno == EINTR);
  if (n < 0) {
    if (errno == EAGAIN || errno == EWOULDBLOCK) return std::nullopt;
    throw std::runtime_error(std::string("LCM: receiving a datagram failed: ") + std::strerror(errno));
  }
  for (cmsghdr* c = CMSG_FIRSTHDR(&m); c != nullptr; c = CMSG_NXTHDR(&m, c)) {
    if (c->cmsg_level == SOL_SOCKET && c->cmsg_type == SO_RXQ_OVFL) {
      std::uint32_t dropped = 0;
      std::memcpy(&dropped, CMSG_DATA(c), sizeof dropped);
      kernel_dropped_ = dropped;
    }
  }
  Received r;
  r.sender = Sender{ntohl(from.sin_addr.s_addr), ntohs(from.sin_port)};
  // A datagram cut to the buffer (impossible with kDatagramBufferBytes over IPv4) is given
  // as empty, so that it is counted malformed rather than read in part.
  r.size = (m.msg_flags & MSG_TRUNC) != 0 ? 0 : static_cast<std::size_t>(n);
  return r;
}

}  // namespace dvpr::udpm
