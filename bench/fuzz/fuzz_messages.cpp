// SPDX-License-Identifier: BSD-3-Clause
// libFuzzer harness over genmros' decoders (build and run: bench/fuzz/fuzz.py).
//
// An input is [type selector][mode][wire image]. For the selected type it
// checks, under AddressSanitizer and UndefinedBehaviorSanitizer:
//   - the safe API on a fresh message: deserialize(buf, size) reads only
//     within size; what it accepts re-serializes to the very bytes consumed,
//     and serialize() refuses a buffer one byte short;
//   - a reused (dirty) message, decoded into again and again across inputs,
//     gives the same result as a fresh one;
//   - mROS v1 delivery (CallCallbackFuncs) of an outside frame, whose length
//     word may claim less than the image, and of an on-board frame written
//     by memCopy behind a stale length word: the callback runs exactly when
//     the body decodes, with the message a fresh decode gives.
// Compiles as C++98, so it also covers the mROS v1 language mode.
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <vector>

#include "fuzz_types.h"  // written by fuzz.py: the headers and GENMROS_FUZZ_TYPES(F)

namespace {

std::vector<uint8_t> g_expected;
bool g_delivered = false;

// On-board blocks come from this arena and outside frames from the heap, as
// in the mROS v1 library (publishers' pool blocks versus received frames).
char g_block_arena[1 << 20];

void require(bool condition, const char* what) {
  if (!condition) {
    fprintf(stderr, "genmros fuzz: %s\n", what);
    abort();
  }
}

template <class T> std::vector<uint8_t> encode(const T& message) {
  std::vector<uint8_t> out(message.serializedLength() + 1);
  const int32_t written = message.serialize(&out[0], static_cast<uint32_t>(out.size() - 1));
  require(written == static_cast<int32_t>(out.size() - 1), "serialize() disagrees with serializedLength()");
  out.pop_back();
  return out;
}

template <class T> void onDelivery(void* message) {
  require(!g_delivered, "callback ran twice");
  g_delivered = true;
  require(encode(*static_cast<T*>(message)) == g_expected, "delivered message differs from a fresh decode");
}

// The result of a fresh decode of size bytes: consumed bytes (or -1) and,
// when accepted, the re-encoded image.
template <class T> int32_t decodeFresh(const uint8_t* data, uint32_t size, std::vector<uint8_t>& image) {
  T message;
  const int32_t consumed = message.deserialize(data, size);
  image.clear();
  if (consumed >= 0) {
    require(static_cast<uint32_t>(consumed) <= size, "consumed more than given");
    image = encode(message);
    require(image.size() == static_cast<size_t>(consumed) &&
                (consumed == 0 || memcmp(&image[0], data, consumed) == 0),
            "re-serialization differs from the bytes consumed");
    uint8_t* short_buffer = static_cast<uint8_t*>(malloc(consumed > 0 ? consumed - 1 + 1 : 1));
    if (consumed > 0) {
      require(message.serialize(short_buffer, static_cast<uint32_t>(consumed - 1)) == -1,
              "serialize() accepted a buffer one byte short");
    }
    free(short_buffer);
  }
  return consumed;
}

template <class T> void deliverOutsideFrame(const uint8_t* data, uint32_t size, uint32_t claimed) {
  std::vector<uint8_t> expected;
  const int32_t consumed = decodeFresh<T>(data, claimed, expected);
  char* frame = static_cast<char*>(malloc(4 + size));
  for (int i = 0; i < 4; ++i) frame[i] = static_cast<char>(claimed >> (8 * i));
  if (size) memcpy(frame + 4, data, size);
  g_expected = expected;
  g_delivered = false;
  subtask_methods::CallCallbackFuncs<T::MROS_TYPE_ID>::call(&onDelivery<T>, frame,
                                                            mros::wire::kFrameSizeUnknown);
  require(g_delivered == (consumed >= 0), "outside frame: delivery does not match the decode");
  // As genmros' patch set for the library hands it over: with the frame's
  // size, which bounds the read whatever the length word claims.
  std::vector<uint8_t> expected_within_size;
  const int32_t consumed_within_size = decodeFresh<T>(data, size, expected_within_size);
  g_expected = expected_within_size;
  g_delivered = false;
  subtask_methods::CallCallbackFuncs<T::MROS_TYPE_ID>::call(&onDelivery<T>, frame, 4 + size);
  require(g_delivered == (consumed_within_size >= 0),
          "sized frame: delivery does not match the decode");
  free(frame);
}

template <class T> void deliverOnBoardFrame(const uint8_t* data, uint32_t size) {
  T message;
  if (message.deserialize(data, size) < 0) return;
  const int body = message.dataSize();
  if (4 + static_cast<size_t>(body) > sizeof(g_block_arena)) return;
  memset(g_block_arena, 0xff, 4);  // the library never wrote this block's length word
  char* cursor = g_block_arena + 4;
  message.memCopy(cursor);
  require(cursor == g_block_arena + 4 + body, "memCopy() wrote other than dataSize() bytes");
  g_expected = encode(message);
  g_delivered = false;
  subtask_methods::CallCallbackFuncs<T::MROS_TYPE_ID>::call(&onDelivery<T>, g_block_arena,
                                                            mros::wire::kFrameSizeUnknown);
  require(g_delivered, "on-board frame not delivered");
}

template <class T> void fuzzType(const uint8_t* data, uint32_t size, uint8_t mode) {
  std::vector<uint8_t> image;
  const int32_t consumed = decodeFresh<T>(data, size, image);

  static T dirty;
  const int32_t again = dirty.deserialize(data, size);
  require(again == consumed, "a reused message decodes to another length");
  if (again >= 0) require(encode(dirty) == image, "a reused message decodes to other values");

  const uint32_t claimed = (mode & 1) ? size : size - (size >> (1 + (mode >> 1) % 8));
  deliverOutsideFrame<T>(data, size, claimed);
  deliverOnBoardFrame<T>(data, size);
}

typedef void (*Fuzzer)(const uint8_t*, uint32_t, uint8_t);
#define GENMROS_FUZZER_OF(T) &fuzzType<T>,
const Fuzzer kFuzzers[] = {GENMROS_FUZZ_TYPES(GENMROS_FUZZER_OF)};
const size_t kFuzzerCount = sizeof(kFuzzers) / sizeof(kFuzzers[0]);

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 2 || size > 0x7fffffffu) return 0;
  kFuzzers[data[0] % kFuzzerCount](data + 2, static_cast<uint32_t>(size - 2), data[1]);
  return 0;
}
