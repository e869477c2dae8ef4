// SPDX-License-Identifier: BSD-3-Clause
// lwIP's error codes (lwip/err.h): the values lwIP gives them.
#ifndef MROS2_PC_LWIP_ERR_H
#define MROS2_PC_LWIP_ERR_H

#include "lwip/arch.h"

typedef s8_t err_t;

enum {
  ERR_OK = 0,
  ERR_MEM = -1,
  ERR_BUF = -2,
  ERR_RTE = -4,
  ERR_VAL = -6,
  ERR_USE = -8,
  ERR_ARG = -16
};

#endif  // MROS2_PC_LWIP_ERR_H
