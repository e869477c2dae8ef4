// SPDX-License-Identifier: BSD-3-Clause
// The program of bench/mros2/fragment_speed.py: how long publishing a large
// message takes through copyToBuf and through mros2's fragments, for the
// types the script exports with genmros (frag_bench/msg/*: Items, Numbers,
// Groups), filled to a given image size.
//
//   fragment_speed time SECONDS ROUNDS KB...   one line per type and size:
//     "TYPE KB IMAGE_BYTES WHOLE_NS FRAGMENTS_NS FRAGMENTS SIZEOF"
//   fragment_speed once TYPE KB whole|fragments  one publication, for callgrind
//     (the script collects inside measure_whole / measure_fragments only)
//
// Each publication is checked first: the fragments must carry the header,
// copyToBuf's image and its padding to 4, as mros2's runtime sends them.
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <algorithm>
#include <chrono>
#include <string>
#include <vector>

#include "frag_bench/msg/groups.hpp"
#include "frag_bench/msg/items.hpp"
#include "frag_bench/msg/numbers.hpp"

using frag_bench::msg::Groups;
using frag_bench::msg::Item;
using frag_bench::msg::Items;
using frag_bench::msg::Numbers;

namespace {

// Items per group of Groups.
const uint32_t kGroupItems = 16;
// mros2's fragment buffer (src/mros2.cpp): the first fragment holds the
// 4-byte encapsulation header and 60 bytes of the image, the others 64.
const uint32_t kFragmentBuffer = 64;
const uint8_t kHeader[4] = {0, 1, 0, 0};

// Fixed-width names: every item takes the same bytes.
std::string item_name(uint32_t index) {
  char name[32];
  snprintf(name, sizeof name, "item-%08u", index);
  return name;
}

void fill(Item& item, uint32_t index) {
  item.id = static_cast<int32_t>(index);
  item.value = index * 0.5;
  item.name = item_name(index);
}
void fill(Items& message, uint32_t count) {
  message.items.resize(count);
  for (uint32_t i = 0; i < count; ++i) fill(message.items[i], i);
}
void fill(Numbers& message, uint32_t count) {
  message.data.resize(count);
  message.blob.resize(4 * count);
  for (uint32_t i = 0; i < count; ++i) message.data[i] = i * 0.25;
  for (uint32_t i = 0; i < 4 * count; ++i) message.blob[i] = static_cast<uint8_t>(i);
  message.label = "numbers";
}
void fill(Groups& message, uint32_t count) {
  message.groups.resize(count);
  for (uint32_t i = 0; i < count; ++i) fill(message.groups[i], kGroupItems);
}

// The message with the most elements whose image is at most bytes long.
template <class T> void fill_to(T& message, uint32_t bytes) {
  uint32_t low = 0, high = 1;
  for (;;) {
    fill(message, high);
    if (message.calcRawTotalSize() > bytes) break;
    low = high;
    high *= 2;
  }
  while (high - low > 1) {
    uint32_t middle = low + (high - low) / 2;
    fill(message, middle);
    (message.calcRawTotalSize() > bytes ? high : low) = middle;
  }
  fill(message, low);
}

// Keeps the compiler from dropping work whose result nobody reads.
template <class T> void escape(T* p) { asm volatile("" : : "g"(p) : "memory"); }

template <class T> __attribute__((noinline)) void measure_whole(T& message, uint8_t* buffer) {
  message.copyToBuf(buffer);
  message.resetCount();
  escape(buffer);
}

// The copyToFragBuf calls of one publication, as src/mros2.cpp makes them:
// until one says all is written and wrote nothing, then resetCount. Each
// fragment goes to sent if given. Returns the calls made.
template <class T>
__attribute__((noinline)) uint32_t measure_fragments(T& message, std::vector<uint8_t>* sent) {
  uint8_t fragment[kFragmentBuffer];
  for (uint32_t calls = 1;; ++calls) {
    uint32_t offset = 0;
    if (message.getPubCnt() == 0) {
      offset = 4;
      memcpy(fragment, kHeader, 4);
    }
    typename T::FragCopyReturnType done =
        message.copyToFragBuf(fragment + offset, kFragmentBuffer - offset);
    uint32_t length = done.second + offset;
    if (done.first && done.second > 0) {
      while (length % 4) fragment[length++] = 0;
    }
    escape(fragment);
    if (sent) sent->insert(sent->end(), fragment, fragment + length);
    if (done.first && done.second == 0) {
      message.resetCount();
      return calls;
    }
  }
}

// ns per call of f: loops of about seconds each, the median of rounds; a
// call that takes seconds or more on its own is timed once.
template <class F> double time_ns(F f, double seconds, int rounds) {
  typedef std::chrono::steady_clock clock;
  long iterations = 1;
  for (;;) {
    clock::time_point start = clock::now();
    for (long i = 0; i < iterations; ++i) f();
    double took = std::chrono::duration<double>(clock::now() - start).count();
    if (iterations == 1 && took >= seconds) return took * 1e9;
    if (took >= seconds / 10) {
      iterations = std::max(1L, static_cast<long>(iterations * seconds / took));
      break;
    }
    iterations *= 4;
  }
  std::vector<double> samples;
  for (int r = 0; r < rounds; ++r) {
    clock::time_point start = clock::now();
    for (long i = 0; i < iterations; ++i) f();
    samples.push_back(std::chrono::duration<double, std::nano>(clock::now() - start).count() /
                      iterations);
  }
  std::sort(samples.begin(), samples.end());
  return samples[samples.size() / 2];
}

template <class T> void check(T& message, const char* name) {
  uint32_t size = message.calcRawTotalSize();
  std::vector<uint8_t> expected(4 + size + 3, 0);
  memcpy(&expected[0], kHeader, 4);
  message.copyToBuf(&expected[4]);
  message.resetCount();
  expected.resize(4 + size + (4 - size % 4) % 4);
  for (int publication = 0; publication < 2; ++publication) {
    std::vector<uint8_t> sent;
    measure_fragments(message, &sent);
    if (sent != expected || message.calcTotalSize() != expected.size()) {
      fprintf(stderr, "%s: the fragments are not copyToBuf's image\n", name);
      exit(1);
    }
  }
}

template <class T>
void time_type(const char* name, uint32_t kb, double seconds, int rounds) {
  T message;
  fill_to(message, kb * 1024);
  check(message, name);
  uint32_t size = message.calcRawTotalSize();
  std::vector<uint8_t> buffer(size + 4);
  double whole = time_ns([&] { measure_whole(message, &buffer[0]); }, seconds, rounds);
  uint32_t calls = 0;
  double fragments = time_ns([&] { calls = measure_fragments(message, 0); }, seconds, rounds);
  printf("%s %u %u %.1f %.1f %u %zu\n", name, kb, size, whole, fragments, calls, sizeof(T));
  fflush(stdout);
}

template <class T> void once(uint32_t kb, bool fragments) {
  T message;
  fill_to(message, kb * 1024);
  std::vector<uint8_t> buffer(message.calcRawTotalSize() + 4);
  if (fragments)
    printf("%u\n", measure_fragments(message, 0));
  else
    measure_whole(message, &buffer[0]);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc >= 4 && strcmp(argv[1], "time") == 0) {
    double seconds = atof(argv[2]);
    int rounds = atoi(argv[3]);
    for (int i = 4; i < argc; ++i) {
      uint32_t kb = static_cast<uint32_t>(atoi(argv[i]));
      time_type<Items>("Items", kb, seconds, rounds);
      time_type<Numbers>("Numbers", kb, seconds, rounds);
      time_type<Groups>("Groups", kb, seconds, rounds);
    }
    return 0;
  }
  if (argc == 5 && strcmp(argv[1], "once") == 0) {
    uint32_t kb = static_cast<uint32_t>(atoi(argv[3]));
    bool fragments = strcmp(argv[4], "fragments") == 0;
    if (strcmp(argv[2], "Items") == 0) once<Items>(kb, fragments);
    if (strcmp(argv[2], "Numbers") == 0) once<Numbers>(kb, fragments);
    if (strcmp(argv[2], "Groups") == 0) once<Groups>(kb, fragments);
    return 0;
  }
  fprintf(stderr, "usage: %s time SECONDS ROUNDS KB... | once TYPE KB whole|fragments\n",
          argv[0]);
  return 2;
}
