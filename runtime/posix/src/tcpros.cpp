// tcpros.cpp: TCPROS header and frame I/O (see tcpros.h).
#include "tcpros.h"

#include "net.h"

namespace mros {
namespace posix {
namespace tcpros {

namespace {

void putLength(std::string& out, uint32_t length) {
  for (int i = 0; i < 4; ++i) {
    out += static_cast<char>((length >> (8 * i)) & 0xFF);
  }
}

uint32_t getLength(const uint8_t* bytes) {
  return static_cast<uint32_t>(bytes[0]) | static_cast<uint32_t>(bytes[1]) << 8 |
         static_cast<uint32_t>(bytes[2]) << 16 | static_cast<uint32_t>(bytes[3]) << 24;
}

bool readLength(int fd, uint32_t& length, const net::Deadline& deadline) {
  uint8_t bytes[4];
  if (!net::receiveAll(fd, bytes, sizeof(bytes), deadline)) {
    return false;
  }
  length = getLength(bytes);
  return true;
}

}  // namespace

bool writeHeader(int fd, const Header& header) {
  std::string fields;
  for (const auto& entry : header) {
    putLength(fields, static_cast<uint32_t>(entry.first.size() + 1 + entry.second.size()));
    fields += entry.first + "=" + entry.second;
  }
  std::string wire;
  putLength(wire, static_cast<uint32_t>(fields.size()));
  wire += fields;
  return net::sendAll(fd, wire.data(), wire.size());
}

bool readHeader(int fd, Header& header, std::string& error, const net::Deadline& deadline) {
  uint32_t length = 0;
  if (!readLength(fd, length, deadline)) {
    error = "connection closed before the header";
    return false;
  }
  if (length > kMaxHeaderBytes) {
    error = "header of " + std::to_string(length) + " bytes exceeds the limit of " +
            std::to_string(kMaxHeaderBytes);
    return false;
  }
  std::vector<uint8_t> bytes;
  if (!net::receiveGrowing(fd, bytes, length, deadline)) {
    error = "connection closed inside the header, or the header came too slowly";
    return false;
  }
  header.clear();
  uint32_t pos = 0;
  while (pos < length) {
    if (length - pos < 4) {
      error = "header field length truncated";
      return false;
    }
    const uint32_t field_length = getLength(&bytes[pos]);
    pos += 4;
    if (field_length > length - pos) {
      error = "header field runs past the end of the header";
      return false;
    }
    const std::string text(reinterpret_cast<const char*>(&bytes[pos]), field_length);
    pos += field_length;
    const size_t equals = text.find('=');
    if (equals == std::string::npos) {
      error = "header field without '='";
      return false;
    }
    header[text.substr(0, equals)] = text.substr(equals + 1);
  }
  return true;
}

FrameStatus readFrame(int fd, std::vector<uint8_t>& body, std::string& error) {
  uint32_t length = 0;
  if (!readLength(fd, length, net::Deadline::none())) {
    error = "connection closed";
    return kStreamEnded;
  }
  if (length > kMaxMessageBytes) {
    error = "message length " + std::to_string(length) + " exceeds the limit of " +
            std::to_string(kMaxMessageBytes) + " bytes";
    return kFrameTooLarge;
  }
  if (!net::receiveGrowing(fd, body, length)) {
    error = "connection closed inside a message";
    return kStreamEnded;
  }
  return kFrameRead;
}

std::string field(const Header& header, const std::string& key) {
  const auto found = header.find(key);
  return found == header.end() ? std::string() : found->second;
}

}  // namespace tcpros
}  // namespace posix
}  // namespace mros
