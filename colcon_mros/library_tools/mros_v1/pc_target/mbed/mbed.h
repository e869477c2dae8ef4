/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * mbed 2's API as the mROS v1 sample apps use it, on a PC. Pins are not
 * hardware: an output's every change is logged ("P6_13 0.78125" to stderr,
 * or to the file MROS_PC_OUTPUT_LOG names), and inputs are read from the
 * file MROS_PC_INPUTS names (lines "P6_0 1"; a pin it does not name reads
 * 0), which a test or a user edits while the app runs; InterruptIn's rise
 * and fall handlers run, at interrupt level, when a pin's value there
 * changes. Tickers and timeouts run their handlers at interrupt level;
 * wait()/wait_ms() let other tasks run (dly_tsk); wait_us() spins.
 */
#ifndef MROS_PC_TARGET_MBED_H
#define MROS_PC_TARGET_MBED_H

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdint.h>

#include "PinNames.h"

extern "C" void mbed_mac_address(char *mac);

namespace mbed {

void wait(float seconds);
void wait_ms(int milliseconds);
void wait_us(int microseconds);

class DigitalOut {
 public:
  explicit DigitalOut(PinName pin);
  DigitalOut(PinName pin, int value);
  void write(int value);
  int read();
  DigitalOut &operator=(int value);
  DigitalOut &operator=(DigitalOut &other);
  operator int();

 private:
  PinName pin_;
  int value_;
};

class DigitalIn {
 public:
  explicit DigitalIn(PinName pin);
  DigitalIn(PinName pin, PinMode mode);
  int read();
  void mode(PinMode pull);
  operator int();

 private:
  PinName pin_;
};

class InterruptIn {
 public:
  explicit InterruptIn(PinName pin);
  int read();
  operator int();
  void rise(void (*handler)(void));
  void fall(void (*handler)(void));
  void mode(PinMode pull);
  void enable_irq();
  void disable_irq();

 private:
  PinName pin_;
};

class Timer {
 public:
  Timer();
  void start();
  void stop();
  void reset();
  float read();
  int read_ms();
  int read_us();
  operator float();

 private:
  uint64_t started_us_;
  uint64_t elapsed_us_;
  bool running_;
};

class Ticker {
 public:
  Ticker();
  virtual ~Ticker();
  void attach(void (*handler)(void), float seconds);
  void attach_us(void (*handler)(void), uint64_t microseconds);
  void detach();

 protected:
  void start(void (*handler)(void), uint64_t first_us, uint64_t period_us);

 private:
  Ticker(const Ticker &);
  Ticker &operator=(const Ticker &);
  static void call(void *ticker);
  void (*handler_)(void);
  int timer_;  // the kernel timer's handle, -1 when detached
};

class Timeout : public Ticker {
 public:
  void attach(void (*handler)(void), float seconds);
  void attach_us(void (*handler)(void), uint64_t microseconds);
};

}  // namespace mbed

using namespace mbed;
using namespace std;

#endif /* MROS_PC_TARGET_MBED_H */
