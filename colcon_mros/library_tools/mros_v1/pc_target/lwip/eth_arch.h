/* SPDX-License-Identifier: BSD-3-Clause */
/* mbed's Ethernet driver interface for lwIP, on a PC: no driver to start. */
#ifndef MROS_PC_TARGET_ETH_ARCH_H
#define MROS_PC_TARGET_ETH_ARCH_H

#include "lwip/netif.h"

#ifdef __cplusplus
extern "C" {
#endif

err_t eth_arch_enetif_init(struct netif *netif);
void eth_arch_enable_interrupts(void);
void eth_arch_disable_interrupts(void);

#ifdef __cplusplus
}
#endif

#endif /* MROS_PC_TARGET_ETH_ARCH_H */
