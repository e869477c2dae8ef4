// net.h: the few POSIX socket operations the node needs, with the timeouts
// and partial-transfer handling done once, here.
#ifndef MROS_POSIX_NET_H
#define MROS_POSIX_NET_H

#include <cstddef>
#include <cstdint>
#include <string>

namespace mros {
namespace posix {
namespace net {

struct HostPort {
  std::string host;
  uint16_t port;
};

// Parses "http://host:port/..." (the form of ROS master and slave URIs).
bool parseHttpUri(const std::string& uri, HostPort& out);

// Listening TCP socket on bind_address ("" for every address) and a port the
// kernel chooses; returns the fd (or -1) and stores the port.
int listenTcp(const std::string& bind_address, uint16_t& port);

// Connects within timeout_ms; returns the fd or -1 (errno_text says why).
int connectTcp(const HostPort& peer, int timeout_ms, std::string& error_text);

// Both directions give up after timeout_ms of silence (0: never).
void setTimeouts(int fd, int timeout_ms);
void setNoDelay(int fd);

// Whole transfers: false on error, timeout or end of stream.
bool sendAll(int fd, const void* data, size_t size);
bool receiveAll(int fd, void* data, size_t size);

}  // namespace net
}  // namespace posix
}  // namespace mros

#endif  // MROS_POSIX_NET_H
