/* SPDX-License-Identifier: BSD-3-Clause */
/* The SoftPWM library (software PWM on any pin) on a PC: the duty cycle is
 * an output, logged on every change (see mbed.h). */
#ifndef MROS_PC_TARGET_SOFTPWM_H
#define MROS_PC_TARGET_SOFTPWM_H

#include "mbed.h"

class SoftPWM {
 public:
  explicit SoftPWM(PinName pin, bool positive = true);
  void write(float duty);
  float read();
  void period(float seconds);
  void period_ms(int milliseconds);
  void period_us(int microseconds);
  void pulsewidth(float seconds);
  void pulsewidth_ms(int milliseconds);
  void pulsewidth_us(int microseconds);
  void start();
  void stop();
  SoftPWM &operator=(float duty);
  SoftPWM &operator=(SoftPWM &other);
  operator float();

 private:
  PinName pin_;
  float duty_;
  int period_us_;
};

#endif /* MROS_PC_TARGET_SOFTPWM_H */
