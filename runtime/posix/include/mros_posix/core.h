// core.h: the type-independent mROS communication library for POSIX, as the
// API layer (ros_api.cpp) calls it. Nothing here names a message type: a
// topic's type is described by its name, MD5 sum and definition text, which
// the API layer obtains from the generated type-specific functions, and
// received messages are decoded by a function the API layer instantiates per
// type (the paper's split between common and type-specific processes).
#ifndef MROS_POSIX_CORE_H
#define MROS_POSIX_CORE_H

#include <cstdint>
#include <memory>
#include <string>

namespace mros {
namespace posix {

class Publication;
class Subscription;

// What the master and the TCPROS handshake compare.
struct TopicType {
  std::string datatype;
  std::string md5sum;
  std::string definition;
};

// One serialized message as it goes on the wire: a uint32 little-endian body
// length followed by the body. Shared by every connection that sends it.
class Frame {
 public:
  explicit Frame(uint32_t body_size);
  uint8_t* body() { return bytes_.get() + 4; }
  uint32_t bodySize() const { return body_size_; }
  const uint8_t* wire() const { return bytes_.get(); }
  uint32_t wireSize() const { return body_size_ + 4; }

 private:
  std::unique_ptr<uint8_t[]> bytes_;
  uint32_t body_size_;
};

// Decodes a received body and, if it is a complete message of the topic's
// type, passes it to callback. Returns false for a malformed body.
typedef bool (*Deliverer)(void (*callback)(void*), const uint8_t* body, uint32_t size);

void initNode(int argc, char** argv, const std::string& node_name);
bool ok();
void spin();

// Registers with the master; returns the node's publication of the topic.
Publication* advertise(const std::string& topic, const TopicType& type, int queue_size);
// Hands a frame to every connected subscriber's sending queue.
void publish(Publication* publication, std::shared_ptr<const Frame> frame);

// Callbacks run, one at a time, on the receiving threads as frames arrive;
// TCP flow control bounds the backlog, so there is no receive queue to size.
Subscription* subscribe(const std::string& topic, const TopicType& type, Deliverer deliverer,
                        void (*callback)(void*));

}  // namespace posix
}  // namespace mros

#endif  // MROS_POSIX_CORE_H
