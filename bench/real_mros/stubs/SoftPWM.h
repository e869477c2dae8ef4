// Stand-in for the SoftPWM library of the mROS v1 sample apps.
#ifndef STUB_SOFTPWM_H
#define STUB_SOFTPWM_H
#include "mbed.h"
class SoftPWM {
 public:
  explicit SoftPWM(PinName pin);
  void period_ms(int milliseconds);
  SoftPWM& operator=(float duty);
  operator float();
};
#endif
