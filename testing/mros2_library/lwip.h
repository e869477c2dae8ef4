// SPDX-License-Identifier: BSD-3-Clause
// mros2.h includes the port's lwip.h; mros2_init calls its MX_LWIP_Init.
#ifndef MROS2_LIBRARY_STAND_IN_LWIP_H
#define MROS2_LIBRARY_STAND_IN_LWIP_H
void MX_LWIP_Init(void);
#endif
