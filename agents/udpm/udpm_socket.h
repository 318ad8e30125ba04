#pragma once
// The receiving socket of an LCM UDP multicast group, opened as LCM opens its own
// (lcm/lcm_udpm.c): SO_REUSEADDR and SO_REUSEPORT, so that every other LCM process on this
// machine and URL (lcm-spy, lcm-logger, the other agents) binds the same port and gets its own
// copy of every datagram; bound to the group address and port; joined to the group on the
// default interface. The membership is taken before the bind, so a socket that shows in
// /proc/net/udp already receives. Non-blocking: Receive() returns what is waiting.
//
// SO_RXQ_OVFL is on: every datagram read carries the kernel's count of datagrams it dropped
// because this socket's buffer was full, so losses to a slow reader are counted, not silent.
#include <cstdint>
#include <optional>
#include <span>

#include "agents/udpm/udpm_reassembler.h"
#include "agents/udpm/udpm_url.h"

namespace dvpr::udpm {

// Large enough for any UDP datagram over IPv4 (65507 bytes of payload).
inline constexpr std::size_t kDatagramBufferBytes = 65536;

class Socket {
 public:
  // Throws std::runtime_error naming the group and the failing step (no multicast route, ...).
  explicit Socket(const Url& url);
  ~Socket();
  Socket(const Socket&) = delete;
  Socket& operator=(const Socket&) = delete;

  int fd() const { return fd_; }

  struct Received {
    Sender sender;
    std::size_t size = 0;  // bytes written to the buffer
  };
  // Reads one waiting datagram into `buffer` (kDatagramBufferBytes); nullopt when none waits.
  std::optional<Received> Receive(std::span<std::uint8_t> buffer);

  // Datagrams the kernel dropped for a full receive buffer, as of the last one read.
  std::uint64_t kernel_dropped() const { return kernel_dropped_; }
  // The receive buffer the kernel granted (it caps recv_buf_size at net.core.rmem_max).
  int receive_buffer_bytes() const { return receive_buffer_bytes_; }

 private:
  int fd_ = -1;
  std::uint64_t kernel_dropped_ = 0;
  int receive_buffer_bytes_ = 0;
};

}  // namespace dvpr::udpm
