// SPDX-License-Identifier: BSD-3-Clause
// The board's app: the paper's evaluation (Fig. 6 and Fig. 7) and a relay of
// four more test_ws types, on the genmros headers alone. Every message is
// decoded with the length-checked interface and encoded anew, so what the
// ROS nodes get back shows the headers' wire code, byte for byte.
#include "board.h"

#include <stdio.h>

#include <message_headers.h>

namespace board {
namespace {

// The paper's topics, then for every relayed type T four topics: the app
// takes /rospy_out/T and sends it on /board_out/T, takes /roscpp_out/T and
// sends it on /board_back/T.
enum { kPaperOut, kPaperIn, kFirstRelay };
const char* const kRelayed[] = {"PersonalData", "BuiltinTypes", "ArrayTypes", "NestedTypes",
                                "Header"};
enum { kRelayedTypes = sizeof kRelayed / sizeof kRelayed[0], kTopicsPerType = 4 };
enum { kTopics = kFirstRelay + kRelayedTypes * kTopicsPerType };
const char* const kRelayTopics[kTopicsPerType] = {"/rospy_out/", "/board_out/", "/roscpp_out/",
                                                  "/board_back/"};

typedef void (*Handler)(const uint8_t* body, uint32_t size, int index);

struct Entry {
  Topic topic;
  Handler handler;  // NULL for a topic the app publishes
  char name[32];
};

Entry entries[kTopics];
// What the app sends, encoded: one message at a time (the port sends it
// before it hands the app the next).
uint8_t encoded[kMaxMessageSize];

template <class T>
void describe(int index, const char* name, Handler handler) {
  Entry& entry = entries[index];
  snprintf(entry.name, sizeof entry.name, "%s", name);
  entry.topic.name = entry.name;
  entry.topic.type = message_traits::DataType<T*>::value();
  entry.topic.md5sum = message_traits::MD5Sum<T::MROS_TYPE_ID>::value();
  entry.topic.definition = message_traits::Definition<T*>::value();
  entry.topic.publishes = handler == NULL;
  entry.handler = handler;
}

void refuse(const char* what, int index, uint32_t size) {
  char line[160];
  snprintf(line, sizeof line, "refused: %s on %s (%lu bytes)", what, entries[index].name,
           static_cast<unsigned long>(size));
  log(line);
}

// Decodes a message of type T and sends it, encoded anew, on the topic
// after this one. The message is static: a NestedTypes does not belong on a
// small task's stack.
template <class T>
void relay(const uint8_t* body, uint32_t size, int index) {
  static T message;
  if (message.deserialize(body, size) != static_cast<int32_t>(size)) {
    refuse("a malformed message", index, size);
    return;
  }
  int32_t written = message.serialize(encoded, sizeof encoded);
  if (written < 0) {
    refuse("a message over kMaxMessageSize", index, message.serializedLength());
    return;
  }
  send(index + 1, encoded, static_cast<uint32_t>(written));
}

// Fig. 7: prints what the ROS nodes send.
void hear(const uint8_t* body, uint32_t size, int index) {
  mros_test::PersonalData data;
  if (data.deserialize(body, size) != static_cast<int32_t>(size)) {
    refuse("a malformed message", index, size);
    return;
  }
  char line[200];
  snprintf(line, sizeof line, "heard: %s %s age:%u score:%ld", data.first_name.c_str(),
           data.last_name.c_str(), static_cast<unsigned>(data.age),
           static_cast<long>(data.score));
  log(line);
}

template <class T>
void describeRelay(int type) {
  int first = kFirstRelay + type * kTopicsPerType;
  for (int i = 0; i < kTopicsPerType; ++i) {
    char name[32];
    snprintf(name, sizeof name, "%s%s", kRelayTopics[i], kRelayed[type]);
    describe<T>(first + i, name, i % 2 == 0 ? relay<T> : NULL);
  }
}

}  // namespace

void start() {
  describe<mros_test::PersonalData>(kPaperOut, "/mros_str", NULL);
  describe<mros_test::PersonalData>(kPaperIn, "/test_msg", hear);
  describeRelay<mros_test::PersonalData>(0);
  describeRelay<mros_test::BuiltinTypes>(1);
  describeRelay<mros_test::ArrayTypes>(2);
  describeRelay<mros_test::NestedTypes>(3);
  describeRelay<std_msgs::Header>(4);
}

int topicCount() { return kTopics; }

const Topic& topic(int index) { return entries[index].topic; }

void receive(int index, const uint8_t* body, uint32_t size) {
  if (index < 0 || index >= kTopics) {
    log("refused: a message for a topic the app does not have");
    return;
  }
  if (entries[index].handler == NULL) {
    refuse("a message on a topic the app publishes", index, size);
    return;
  }
  entries[index].handler(body, size, index);
}

// Fig. 6: "Phil Woods", 83, the score counting up, five times a second.
void tick() {
  static mros_test::PersonalData data;
  static unsigned ticks = 0;
  if (ticks++ % 2 != 0) {
    return;
  }
  if (data.first_name.empty()) {
    data.first_name = "Phil";
    data.last_name = "Woods";
    data.age = 83;
    data.score = 100000;
  }
  int32_t written = data.serialize(encoded, sizeof encoded);
  if (written >= 0) {
    send(kPaperOut, encoded, static_cast<uint32_t>(written));
    ++data.score;
  }
}

}  // namespace board
