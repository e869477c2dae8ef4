// xmlrpc_http.cpp: XML-RPC over HTTP/1.x: POSTing a call to a master or
// slave URI, and reading a call / writing an answer on the server side.
// Header and body sizes are bounded, a whole message must arrive within
// kCallTimeoutMs, and a body takes memory as it arrives.
#include <cctype>
#include <cstdlib>
#include <unistd.h>

#include "net.h"
#include "xmlrpc.h"

namespace mros {
namespace posix {
namespace xmlrpc {

namespace {

const size_t kMaxHttpHeaderBytes = 16 * 1024;
const size_t kMaxHttpBodyBytes = 4 * 1024 * 1024;
const int kCallTimeoutMs = 5000;

// Reads an HTTP message (request or response) and returns its body.
bool readHttpMessage(int fd, std::string& body) {
  const net::Deadline deadline = net::Deadline::after(kCallTimeoutMs);
  std::string head;
  char c;
  while (head.size() < kMaxHttpHeaderBytes) {
    if (!net::receiveAll(fd, &c, 1, deadline)) {
      return false;
    }
    head += c;
    if (head.size() >= 4 && head.compare(head.size() - 4, 4, "\r\n\r\n") == 0) {
      break;
    }
  }
  if (head.size() >= kMaxHttpHeaderBytes) {
    return false;
  }
  long long length = -1;
  size_t line = head.find("\r\n");
  while (line != std::string::npos && line + 2 < head.size()) {
    const size_t next = head.find("\r\n", line + 2);
    std::string field = head.substr(line + 2, next - line - 2);
    for (size_t i = 0; i < field.size() && field[i] != ':'; ++i) {
      field[i] = static_cast<char>(std::tolower(static_cast<unsigned char>(field[i])));
    }
    if (field.compare(0, 15, "content-length:") == 0) {
      length = std::atoll(field.c_str() + 15);
    }
    line = next;
  }
  if (length > static_cast<long long>(kMaxHttpBodyBytes)) {
    return false;
  }
  body.clear();
  if (length >= 0) {
    return net::receiveGrowing(fd, body, static_cast<size_t>(length), deadline);
  }
  char chunk[4096];  // no Content-Length: the body ends with the connection
  for (;;) {
    if (deadline.remainingMs() == 0) {
      return false;
    }
    const ssize_t received = read(fd, chunk, sizeof(chunk));
    if (received <= 0) {
      return received == 0;
    }
    body.append(chunk, static_cast<size_t>(received));
    if (body.size() > kMaxHttpBodyBytes) {
      return false;
    }
  }
}

}  // namespace

bool call(const std::string& uri, const std::string& method, const std::vector<Value>& params,
          Value& result, std::string& error) {
  net::HostPort peer;
  if (!net::parseHttpUri(uri, peer)) {
    error = "not an http://host:port/ URI: " + uri;
    return false;
  }
  const int fd = net::connectTcp(peer, kCallTimeoutMs, error);
  if (fd < 0) {
    error = "cannot connect to " + uri + ": " + error;
    return false;
  }
  net::setTimeouts(fd, kCallTimeoutMs);
  const std::string body = encodeCall(method, params);
  const std::string request = "POST /RPC2 HTTP/1.1\r\nHost: " + peer.host + ":" +
                              std::to_string(peer.port) +
                              "\r\nUser-Agent: mros-posix\r\nContent-Type: text/xml\r\n"
                              "Connection: close\r\nContent-Length: " +
                              std::to_string(body.size()) + "\r\n\r\n" + body;
  std::string answer;
  const bool exchanged = net::sendAll(fd, request.data(), request.size()) &&
                         readHttpMessage(fd, answer);
  close(fd);
  if (!exchanged) {
    error = "no valid HTTP answer from " + uri + " to " + method;
    return false;
  }
  return parseResponse(answer, result, error);
}

bool callRosApi(const std::string& uri, const std::string& method,
                const std::vector<Value>& params, Value& value, std::string& error) {
  Value result;
  if (!call(uri, method, params, result, error)) {
    return false;
  }
  if (!result.isArray() || result.items.size() != 3 || !result.items[0].isInt()) {
    error = method + " answered without [code, statusMessage, value]";
    return false;
  }
  if (result.items[0].integer != 1) {
    error = method + " failed: " + result.items[1].text;
    return false;
  }
  value = result.items[2];
  return true;
}

bool readRequest(int fd, std::string& body) { return readHttpMessage(fd, body); }

bool writeResponse(int fd, const std::string& body) {
  const std::string response =
      "HTTP/1.1 200 OK\r\nServer: mros-posix\r\nContent-Type: text/xml\r\n"
      "Connection: close\r\nContent-Length: " +
      std::to_string(body.size()) + "\r\n\r\n" + body;
  return net::sendAll(fd, response.data(), response.size());
}

}  // namespace xmlrpc
}  // namespace posix
}  // namespace mros
