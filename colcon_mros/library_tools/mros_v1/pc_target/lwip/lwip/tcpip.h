/* SPDX-License-Identifier: BSD-3-Clause */
/* lwIP's tcpip thread on a PC: the host's stack runs it; init is done at once. */
#ifndef MROS_PC_TARGET_LWIP_TCPIP_H
#define MROS_PC_TARGET_LWIP_TCPIP_H

#include "lwip/netif.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef void (*tcpip_init_done_fn)(void *arg);
void tcpip_init(tcpip_init_done_fn initfunc, void *arg);
err_t tcpip_input(struct pbuf *p, struct netif *inp);

#ifdef __cplusplus
}
#endif

#endif /* MROS_PC_TARGET_LWIP_TCPIP_H */
