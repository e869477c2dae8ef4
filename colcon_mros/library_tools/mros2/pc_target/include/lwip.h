// SPDX-License-Identifier: BSD-3-Clause
// The board's lwIP start-up (STM32CubeMX's lwip.h, which mros2.h includes):
// MX_LWIP_Init starts the tcpip thread and brings the interface up.
#ifndef MROS2_PC_LWIP_H
#define MROS2_PC_LWIP_H

#include "lwip/netif.h"

#ifdef __cplusplus
extern "C" {
#endif
void MX_LWIP_Init(void);
#ifdef __cplusplus
}
#endif

#endif  // MROS2_PC_LWIP_H
