// SPDX-License-Identifier: BSD-3-Clause
// The board's port for 32-bit ARM Linux (run by qemu-arm): the app's
// messages go through standard input and output to evaluation/board_bridge.py,
// which carries them to and from the ROS graph; log lines go to standard
// error.
//
// A record, either way: uint8 kind, uint16 topic index, uint32 size (both
// little-endian), size bytes. The board sends one 'T' record per topic first
// (name, type, MD5 sum, definition text, each ending in NUL, then 'P' if the
// app publishes, 'S' if it subscribes), then 'M' records (a message body);
// the bridge sends 'M' records.
//
//   board             run against the bridge
//   board --describe  print "name type md5sum P|S" of every topic and exit
#include <errno.h>
#include <poll.h>
#include <stdio.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include <string>

#include "board.h"

namespace {

const int kTickMs = 100;
const size_t kRecordHead = 7;

bool writeAll(const char* data, size_t size) {
  while (size > 0) {
    ssize_t written = write(STDOUT_FILENO, data, size);
    if (written < 0 && errno == EINTR) {
      continue;
    }
    if (written <= 0) {
      return false;
    }
    data += written;
    size -= static_cast<size_t>(written);
  }
  return true;
}

// false at the end of the input or on an error.
bool readAll(uint8_t* data, size_t size) {
  while (size > 0) {
    ssize_t got = read(STDIN_FILENO, data, size);
    if (got < 0 && errno == EINTR) {
      continue;
    }
    if (got <= 0) {
      return false;
    }
    data += got;
    size -= static_cast<size_t>(got);
  }
  return true;
}

void sendRecord(char kind, int index, const uint8_t* body, uint32_t size) {
  std::string record(kRecordHead, '\0');
  record[0] = kind;
  record[1] = static_cast<char>(index & 0xff);
  record[2] = static_cast<char>((index >> 8) & 0xff);
  for (int i = 0; i < 4; ++i) {
    record[3 + i] = static_cast<char>((size >> (8 * i)) & 0xff);
  }
  record.append(reinterpret_cast<const char*>(body), size);
  if (!writeAll(record.data(), record.size())) {
    fprintf(stderr, "board: the bridge is gone\n");
    _exit(1);
  }
}

void announce(int index) {
  const board::Topic& topic = board::topic(index);
  std::string fields;
  const char* values[] = {topic.name, topic.type, topic.md5sum, topic.definition};
  for (size_t i = 0; i < sizeof values / sizeof values[0]; ++i) {
    fields.append(values[i]).push_back('\0');
  }
  fields.push_back(topic.publishes ? 'P' : 'S');
  sendRecord('T', index, reinterpret_cast<const uint8_t*>(fields.data()),
             static_cast<uint32_t>(fields.size()));
}

long nowMs() {
  timespec now;
  clock_gettime(CLOCK_MONOTONIC, &now);
  return now.tv_sec * 1000L + now.tv_nsec / 1000000L;
}

// Reads one record. The size field comes from outside: a body larger than
// the app takes is read and dropped, never stored. false at the end.
bool receiveRecord() {
  static uint8_t body[board::kMaxMessageSize];
  uint8_t head[kRecordHead];
  if (!readAll(head, sizeof head)) {
    return false;
  }
  int index = head[1] | (head[2] << 8);
  uint32_t size = static_cast<uint32_t>(head[3]) | (static_cast<uint32_t>(head[4]) << 8) |
                  (static_cast<uint32_t>(head[5]) << 16) | (static_cast<uint32_t>(head[6]) << 24);
  bool fits = size <= sizeof body;
  for (uint32_t left = size; left > 0;) {
    uint32_t chunk = fits ? left : (left < sizeof body ? left : sizeof body);
    if (!readAll(body + (fits ? size - left : 0), chunk)) {
      return false;
    }
    left -= chunk;
  }
  if (head[0] != 'M' || !fits || index >= board::topicCount()) {
    fprintf(stderr, "board: refused a record (kind %d, topic %d, %lu bytes)\n", head[0], index,
            static_cast<unsigned long>(size));
    return true;
  }
  board::receive(index, body, size);
  return true;
}

}  // namespace

namespace board {

void send(int index, const uint8_t* body, uint32_t size) { sendRecord('M', index, body, size); }

void log(const char* line) { fprintf(stderr, "board: %s\n", line); }

}  // namespace board

int main(int argc, char** argv) {
  setvbuf(stderr, NULL, _IOLBF, 0);
  board::start();
  if (argc > 1 && strcmp(argv[1], "--describe") == 0) {
    for (int i = 0; i < board::topicCount(); ++i) {
      printf("%s %s %s %c\n", board::topic(i).name, board::topic(i).type, board::topic(i).md5sum,
             board::topic(i).publishes ? 'P' : 'S');
    }
    return 0;
  }
  for (int i = 0; i < board::topicCount(); ++i) {
    announce(i);
  }
  long next_tick = nowMs() + kTickMs;
  for (;;) {
    long wait = next_tick - nowMs();
    pollfd input = {STDIN_FILENO, POLLIN, 0};
    int ready = wait > 0 ? poll(&input, 1, static_cast<int>(wait)) : 0;
    if (ready > 0 && !receiveRecord()) {
      return 0;
    }
    if (nowMs() >= next_tick) {
      board::tick();
      next_tick += kTickMs;
    }
  }
}
