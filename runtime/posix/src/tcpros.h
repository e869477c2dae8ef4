// tcpros.h: TCPROS connection headers and message frames. Every length read
// from a peer is checked against a bound before anything is allocated.
#ifndef MROS_POSIX_TCPROS_H
#define MROS_POSIX_TCPROS_H

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "net.h"

namespace mros {
namespace posix {
namespace tcpros {

typedef std::map<std::string, std::string> Header;

// Largest connection header accepted (message definitions of big nested
// types are a few kB).
const uint32_t kMaxHeaderBytes = 256 * 1024;

// Largest message body accepted; a firmware may define a smaller one.
#ifndef MROS_POSIX_MAX_MESSAGE_BYTES
#define MROS_POSIX_MAX_MESSAGE_BYTES (64u * 1024u * 1024u)
#endif
const uint32_t kMaxMessageBytes = MROS_POSIX_MAX_MESSAGE_BYTES;

bool writeHeader(int fd, const Header& header);
// False with a reason for a closed connection, an oversized or malformed
// header (a field without '=' or running past the end), or a header not
// complete by the deadline (a handshake has one, however slowly it trickles).
bool readHeader(int fd, Header& header, std::string& error, const net::Deadline& deadline);

enum FrameStatus { kFrameRead, kStreamEnded, kFrameTooLarge };
// Reads one message frame's body; a length above kMaxMessageBytes is refused
// before anything is allocated, and storage grows with the bytes that
// arrive, not with the length claimed. error says why when no frame was read.
FrameStatus readFrame(int fd, std::vector<uint8_t>& body, std::string& error);

// The value of key, or "" if absent.
std::string field(const Header& header, const std::string& key);

}  // namespace tcpros
}  // namespace posix
}  // namespace mros

#endif  // MROS_POSIX_TCPROS_H
