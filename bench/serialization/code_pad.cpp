// SPDX-License-Identifier: BSD-3-Clause
// Linked between main.o and a side's object, this function of BENCH_CODE_PAD
// bytes (never called) moves every function of the side to another offset
// within cache lines and the decoder's 32-byte windows. run.sh builds each
// side once per pad size; see table.py for why.
#define BENCH_TEXT(x) #x
#define BENCH_SKIP(x) ".skip " BENCH_TEXT(x)
extern "C" void bench_code_pad() { asm volatile(BENCH_SKIP(BENCH_CODE_PAD)); }
