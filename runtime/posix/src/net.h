// net.h: the few POSIX socket operations the node needs, with the timeouts
// and partial-transfer handling done once, here.
#ifndef MROS_POSIX_NET_H
#define MROS_POSIX_NET_H

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
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

// When a whole request must be done by: a peer that trickles bytes is cut
// off at the deadline, however often it sends one.
class Deadline {
 public:
  static Deadline after(int milliseconds) { return Deadline(milliseconds); }
  static Deadline none() { return Deadline(-1); }
  // Milliseconds left (0 once passed), or -1 for no deadline.
  int remainingMs() const;

 private:
  explicit Deadline(int milliseconds);
  bool limited_;
  std::chrono::steady_clock::time_point end_;
};

// Whole transfers: false on error, timeout, deadline or end of stream.
bool sendAll(int fd, const void* data, size_t size);
bool receiveAll(int fd, void* data, size_t size, const Deadline& deadline = Deadline::none());

// Receives size bytes into out (a std::string or std::vector of bytes),
// growing it as bytes arrive rather than to the size a peer claims: a claim
// of megabytes followed by silence costs 64 KiB. Storage a previous message
// really filled is reused at once.
template <class Buffer>
bool receiveGrowing(int fd, Buffer& out, size_t size, const Deadline& deadline = Deadline::none()) {
  static const size_t kFirstChunk = 64 * 1024;
  if (out.capacity() >= size) {
    out.resize(size);
    return size == 0 || receiveAll(fd, &out[0], size, deadline);
  }
  out.clear();
  while (out.size() < size) {
    const size_t have = out.size();
    const size_t chunk = std::min(size - have, std::max(kFirstChunk, have));
    out.resize(have + chunk);
    if (!receiveAll(fd, &out[have], chunk, deadline)) {
      return false;
    }
  }
  return true;
}

// Runs work on a detached thread with a stack of stack_bytes (0: the
// system's default); false, and work not run, when no thread can be made.
bool startThread(std::function<void()> work, size_t stack_bytes = 0);

}  // namespace net
}  // namespace posix
}  // namespace mros

#endif  // MROS_POSIX_NET_H
