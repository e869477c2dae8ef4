// SPDX-License-Identifier: BSD-3-Clause
// libFuzzer harness over the checked decode of genmros' mros2 message classes
// (build and run: bench/fuzz/fuzz_mros2.py).
//
// An input is [type selector][image]: the selector (modulo the type count)
// picks a type, the image is what mros2 hands copyFromBuf after the 4-byte
// encapsulation header. Under AddressSanitizer and UndefinedBehaviorSanitizer
// it checks:
//   - the checked copyFromBuf(image, size) on a fresh message reads only
//     within size, whatever the counts and lengths in the image claim;
//   - what it accepts, copyToBuf writes in exactly calcRawTotalSize() bytes
//     (into a heap block of that size: ASan reports a byte written past it),
//     and calcTotalSize() and getPubCnt() agree with that size: the runtime
//     allocates and sends by them;
//   - that image is a fixed point: the checked copyFromBuf accepts it and
//     copyToBuf writes the same bytes again. The first image may differ
//     from the input (a bool byte 2 becomes 1, padding becomes zeros), but
//     what genmros writes, genmros must read back unchanged;
//   - the checked copyFromBuf refuses that image cut by its last byte: it
//     takes no sample that lacks part of its last value;
//   - copyToFragBuf, driven in 64- (mros2's fragment buffer), 16- and 7-byte
//     fragments with resetCount between, writes the same image: 7 cuts
//     inside every number and padding run;
//   - a message used before (one per type, decoded into by every input of
//     its type) takes and refuses what a fresh one does and decodes to the
//     same message: a decode must overwrite all that an earlier sample or
//     a refused partial read left in sequences and strings.
// A failed check prints what failed to stderr and aborts, so libFuzzer keeps
// the input. At exit it prints how many inputs the checked decode accepted.
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <vector>

#include "fuzz_mros2_types.h"  // written by fuzz_mros2.py: the headers, MROS2_FUZZ_TYPES(F)

namespace {

typedef std::vector<uint8_t> Bytes;

const uint32_t kFragmentSizes[] = {64, 16, 7};

// Inputs run and inputs the checked decode accepted, reported at exit.
struct AcceptanceCount {
  unsigned long inputs = 0;
  unsigned long accepted = 0;
  ~AcceptanceCount() {
    fprintf(stderr, "mros2 fuzz: accepted %lu of %lu inputs\n", accepted, inputs);
  }
};
AcceptanceCount g_count;

void require(bool condition, const char* type_name, const char* what) {
  if (!condition) {
    fprintf(stderr, "mros2 fuzz: %s: %s\n", type_name, what);
    abort();
  }
}

// copyToBuf's image, written into a heap block of exactly calcRawTotalSize()
// bytes, so that a byte more is an ASan report.
template <class T> Bytes encode(T& message, const char* type_name) {
  const uint32_t size = message.calcRawTotalSize();
  uint8_t* block = static_cast<uint8_t*>(malloc(size > 0 ? size : 1));
  message.copyToBuf(block);
  require(message.getPubCnt() == size, type_name, "copyToBuf wrote other than calcRawTotalSize()");
  Bytes image(block, block + size);
  free(block);
  message.resetCount();
  require(message.calcTotalSize() == 4 + size + (4 - size % 4) % 4, type_name,
          "calcTotalSize() is not header + calcRawTotalSize() + padding to 4");
  return image;
}

// The image as copyToFragBuf writes it in fragment_size-byte fragments:
// calls until one says all is written, then resetCount, as mros2's runtime.
template <class T> Bytes encodeInFragments(T& message, uint32_t fragment_size,
                                           const char* type_name) {
  Bytes image;
  Bytes fragment(fragment_size);
  message.resetCount();
  for (;;) {
    const typename T::FragCopyReturnType done = message.copyToFragBuf(&fragment[0], fragment_size);
    require(done.second <= fragment_size, type_name, "copyToFragBuf wrote past its fragment");
    require(done.first || done.second == fragment_size, type_name,
            "copyToFragBuf left a fragment short before the end");
    image.insert(image.end(), fragment.begin(), fragment.begin() + done.second);
    if (done.first) break;
  }
  message.resetCount();
  return image;
}

template <class T> void fuzzType(const uint8_t* data, uint32_t size, const char* type_name) {
  T message;
  const bool accepted = message.copyFromBuf(data, size);
  // Decoded into after every input of its type, taken or refused, so it
  // holds what earlier samples and partial reads left behind.
  static T reused;
  require(reused.copyFromBuf(data, size) == accepted, type_name,
          "a message used before and a fresh one disagree on taking the input");
  if (!accepted) return;
  ++g_count.accepted;
  const Bytes image = encode(message, type_name);
  require(encode(reused, type_name) == image, type_name,
          "a message used before decodes to another message than a fresh one");

  T again;
  require(again.copyFromBuf(image.data(), static_cast<uint32_t>(image.size())), type_name,
          "the checked copyFromBuf refused copyToBuf's image");
  require(encode(again, type_name) == image, type_name,
          "decoding copyToBuf's image and encoding it again gives other bytes");
  // The image ends with a value (calcRawTotalSize() counts no final
  // padding), so the image a byte short holds no whole message.
  T cut;
  require(image.empty() ||
              !cut.copyFromBuf(image.data(), static_cast<uint32_t>(image.size() - 1)),
          type_name, "the checked copyFromBuf took copyToBuf's image cut by a byte");

  for (size_t i = 0; i < sizeof kFragmentSizes / sizeof kFragmentSizes[0]; ++i)
    require(encodeInFragments(message, kFragmentSizes[i], type_name) == image, type_name,
            "copyToFragBuf's fragments differ from copyToBuf's image");
}

typedef void (*Fuzzer)(const uint8_t*, uint32_t, const char*);
#define MROS2_FUZZER_OF(T) &fuzzType<T>,
#define MROS2_NAME_OF(T) #T,
const Fuzzer kFuzzers[] = {MROS2_FUZZ_TYPES(MROS2_FUZZER_OF)};
const char* const kTypeNames[] = {MROS2_FUZZ_TYPES(MROS2_NAME_OF)};
const size_t kTypeCount = sizeof kFuzzers / sizeof kFuzzers[0];

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 1 || size > 0x7fffffffu) return 0;
  ++g_count.inputs;
  const size_t type = data[0] % kTypeCount;
  kFuzzers[type](data + 1, static_cast<uint32_t>(size - 1), kTypeNames[type]);
  return 0;
}
