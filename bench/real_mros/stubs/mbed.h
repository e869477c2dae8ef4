// Stand-in for mbed 2's mbed.h as the mROS v1 sample apps use it: the
// classes they name (declarations only), and, as the real header does, the
// C library headers and `using namespace std`.
#ifndef STUB_MBED_H
#define STUB_MBED_H
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
enum PinName { P2_14, P2_15, P6_0, P6_12, P6_13, P6_14, P6_15 };
class DigitalOut {
 public:
  explicit DigitalOut(PinName pin);
  DigitalOut& operator=(int value);
  operator int();
};
class DigitalIn {
 public:
  explicit DigitalIn(PinName pin);
  int read();
};
class InterruptIn {
 public:
  explicit InterruptIn(PinName pin);
  void rise(void (*handler)());
  void fall(void (*handler)());
};
class Timer {
 public:
  void start();
  void stop();
  void reset();
  int read_us();
};
class Ticker {
 public:
  void attach(void (*handler)(), float seconds);
};
void wait_us(int microseconds);
void wait_ms(int milliseconds);
using namespace std;
#endif
