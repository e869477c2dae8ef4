// net.cpp: socket helpers (see net.h).
#include "net.h"

#include <arpa/inet.h>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <new>
#include <poll.h>
#include <pthread.h>
#include <sys/socket.h>
#include <sys/time.h>
#include <unistd.h>

namespace mros {
namespace posix {
namespace net {

bool parseHttpUri(const std::string& uri, HostPort& out) {
  static const std::string kScheme = "http://";
  if (uri.compare(0, kScheme.size(), kScheme) != 0) {
    return false;
  }
  const size_t host_begin = kScheme.size();
  const size_t colon = uri.find(':', host_begin);
  if (colon == std::string::npos || colon == host_begin) {
    return false;
  }
  const size_t port_end = uri.find('/', colon);
  const std::string port_text = uri.substr(colon + 1, port_end - colon - 1);
  if (port_text.empty() || port_text.size() > 5 ||
      port_text.find_first_not_of("0123456789") != std::string::npos) {
    return false;
  }
  const unsigned long port = std::stoul(port_text);
  if (port == 0 || port > 65535) {
    return false;
  }
  out.host = uri.substr(host_begin, colon - host_begin);
  out.port = static_cast<uint16_t>(port);
  return true;
}

int listenTcp(const std::string& bind_address, uint16_t& port) {
  const int fd = socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (fd < 0) {
    return -1;
  }
  sockaddr_in address;
  std::memset(&address, 0, sizeof(address));
  address.sin_family = AF_INET;
  address.sin_port = 0;
  address.sin_addr.s_addr = htonl(INADDR_ANY);
  if (!bind_address.empty() && inet_pton(AF_INET, bind_address.c_str(), &address.sin_addr) != 1) {
    close(fd);
    return -1;
  }
  socklen_t length = sizeof(address);
  if (bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof(address)) != 0 ||
      listen(fd, 64) != 0 ||
      getsockname(fd, reinterpret_cast<sockaddr*>(&address), &length) != 0) {
    close(fd);
    return -1;
  }
  port = ntohs(address.sin_port);
  return fd;
}

int connectTcp(const HostPort& peer, int timeout_ms, std::string& error_text) {
  addrinfo hints;
  std::memset(&hints, 0, sizeof(hints));
  hints.ai_family = AF_INET;
  hints.ai_socktype = SOCK_STREAM;
  addrinfo* found = nullptr;
  const int lookup = getaddrinfo(peer.host.c_str(), nullptr, &hints, &found);
  if (lookup != 0 || found == nullptr) {
    error_text = "cannot resolve " + peer.host + ": " + gai_strerror(lookup);
    return -1;
  }
  sockaddr_in address;
  std::memcpy(&address, found->ai_addr, sizeof(address));
  freeaddrinfo(found);
  address.sin_port = htons(peer.port);

  const int fd = socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC | SOCK_NONBLOCK, 0);
  if (fd < 0) {
    error_text = std::strerror(errno);
    return -1;
  }
  int result = connect(fd, reinterpret_cast<sockaddr*>(&address), sizeof(address));
  if (result != 0 && errno == EINPROGRESS) {
    pollfd waiting = {fd, POLLOUT, 0};
    if (poll(&waiting, 1, timeout_ms) == 1) {
      int socket_error = 0;
      socklen_t length = sizeof(socket_error);
      getsockopt(fd, SOL_SOCKET, SO_ERROR, &socket_error, &length);
      errno = socket_error;
      result = socket_error == 0 ? 0 : -1;
    } else {
      errno = ETIMEDOUT;
    }
  }
  if (result != 0) {
    error_text = std::strerror(errno);
    close(fd);
    return -1;
  }
  fcntl(fd, F_SETFL, fcntl(fd, F_GETFL) & ~O_NONBLOCK);
  return fd;
}

void setTimeouts(int fd, int timeout_ms) {
  timeval limit;
  limit.tv_sec = timeout_ms / 1000;
  limit.tv_usec = (timeout_ms % 1000) * 1000;
  setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &limit, sizeof(limit));
  setsockopt(fd, SOL_SOCKET, SO_SNDTIMEO, &limit, sizeof(limit));
}

void setNoDelay(int fd) {
  const int on = 1;
  setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &on, sizeof(on));
}

bool sendAll(int fd, const void* data, size_t size) {
  const char* cursor = static_cast<const char*>(data);
  while (size > 0) {
    const ssize_t sent = send(fd, cursor, size, MSG_NOSIGNAL);
    if (sent < 0 && errno == EINTR) {
      continue;
    }
    if (sent <= 0) {
      return false;
    }
    cursor += sent;
    size -= static_cast<size_t>(sent);
  }
  return true;
}

Deadline::Deadline(int milliseconds)
    : limited_(milliseconds >= 0),
      end_(std::chrono::steady_clock::now() + std::chrono::milliseconds(std::max(milliseconds, 0))) {}

int Deadline::remainingMs() const {
  if (!limited_) {
    return -1;
  }
  const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
      end_ - std::chrono::steady_clock::now()).count();
  return left > 0 ? static_cast<int>(left) : 0;
}

bool receiveAll(int fd, void* data, size_t size, const Deadline& deadline) {
  char* cursor = static_cast<char*>(data);
  while (size > 0) {
    const int wait_ms = deadline.remainingMs();
    if (wait_ms >= 0) {
      pollfd readable = {fd, POLLIN, 0};
      const int ready = wait_ms == 0 ? 0 : poll(&readable, 1, wait_ms);
      if (ready < 0 && errno == EINTR) {
        continue;
      }
      if (ready <= 0) {
        return false;
      }
    }
    const ssize_t received = recv(fd, cursor, size, 0);
    if (received < 0 && errno == EINTR) {
      continue;
    }
    if (received <= 0) {
      return false;
    }
    cursor += received;
    size -= static_cast<size_t>(received);
  }
  return true;
}

namespace {

void* runWork(void* work) {
  std::function<void()>* owned = static_cast<std::function<void()>*>(work);
  (*owned)();
  delete owned;
  return nullptr;
}

}  // namespace

bool startThread(std::function<void()> work, size_t stack_bytes) {
  std::function<void()>* owned = new (std::nothrow) std::function<void()>(std::move(work));
  if (owned == nullptr) {
    return false;
  }
  pthread_attr_t attributes;
  pthread_attr_init(&attributes);
  pthread_attr_setdetachstate(&attributes, PTHREAD_CREATE_DETACHED);
  if (stack_bytes != 0) {
    pthread_attr_setstacksize(&attributes, stack_bytes);
  }
  pthread_t thread;
  const int result = pthread_create(&thread, &attributes, runWork, owned);
  pthread_attr_destroy(&attributes);
  if (result != 0) {
    delete owned;
    return false;
  }
  return true;
}

}  // namespace net
}  // namespace posix
}  // namespace mros
