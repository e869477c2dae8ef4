/* SPDX-License-Identifier: BSD-3-Clause */
/* lwIP's ARP on a PC: the host's stack does it; nothing to declare. */
#ifndef MROS_PC_TARGET_NETIF_ETHARP_H
#define MROS_PC_TARGET_NETIF_ETHARP_H
#include "lwip/netif.h"
#endif
