// SPDX-License-Identifier: BSD-3-Clause
// The board's side of the main job: an app written against the genmros
// headers only (no mROS library, no ROS client). It publishes and
// subscribes on the topics of kTopics; a port (port_linux.cpp,
// port_bare_metal.cpp) moves the messages' bytes in and out.
#ifndef EVALUATION_BOARD_H
#define EVALUATION_BOARD_H

#include <stdint.h>

namespace board {

// One topic of the app: the type's identity comes from its genmros header
// (message_traits), so a ROS peer checks it against its own.
struct Topic {
  const char* name;
  const char* type;
  const char* md5sum;
  const char* definition;
  bool publishes;  // else the app subscribes
};

// Called by the port once, before anything else.
void start();
int topicCount();
const Topic& topic(int index);

// The largest message body the app sends or takes.
enum { kMaxMessageSize = 4096 };

// Called by the port: a message body received on topic index, size bytes.
void receive(int index, const uint8_t* body, uint32_t size);
// Called by the port every 100 ms.
void tick();

// Provided by the port.
void send(int index, const uint8_t* body, uint32_t size);
void log(const char* line);

}  // namespace board

#endif  // EVALUATION_BOARD_H
