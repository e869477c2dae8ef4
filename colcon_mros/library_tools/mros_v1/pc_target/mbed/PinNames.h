/* SPDX-License-Identifier: BSD-3-Clause */
/* GR-PEACH's pin names (port * 16 + bit), as mbed 2's PinNames.h has them. */
#ifndef MROS_PC_TARGET_PINNAMES_H
#define MROS_PC_TARGET_PINNAMES_H

#define PC_PORT_PINS(port)                                                                   \
  P##port##_0 = port * 16, P##port##_1, P##port##_2, P##port##_3, P##port##_4, P##port##_5,  \
  P##port##_6, P##port##_7, P##port##_8, P##port##_9, P##port##_10, P##port##_11,            \
  P##port##_12, P##port##_13, P##port##_14, P##port##_15

typedef enum {
  PC_PORT_PINS(0), PC_PORT_PINS(1), PC_PORT_PINS(2), PC_PORT_PINS(3),
  PC_PORT_PINS(4), PC_PORT_PINS(5), PC_PORT_PINS(6), PC_PORT_PINS(7),
  PC_PORT_PINS(8), PC_PORT_PINS(9), PC_PORT_PINS(10), PC_PORT_PINS(11),
  LED_RED = P6_13,
  LED_GREEN = P6_14,
  LED_BLUE = P6_15,
  LED_USER = P6_12,
  LED1 = LED_RED,
  LED2 = LED_GREEN,
  LED3 = LED_BLUE,
  LED4 = LED_USER,
  USER_BUTTON0 = P6_0,
  NC = -1
} PinName;

#undef PC_PORT_PINS

typedef enum { PullUp = 0, PullDown = 3, PullNone = 2, OpenDrain = 4, PullDefault = PullDown } PinMode;

#endif /* MROS_PC_TARGET_PINNAMES_H */
