// SPDX-License-Identifier: BSD-3-Clause
// lwIP's network interface (lwip/netif.h): the board's one interface, with
// the address and netmask embeddedRTPS reads to tell peers in its subnet.
#ifndef MROS2_PC_LWIP_NETIF_H
#define MROS2_PC_LWIP_NETIF_H

#include "lwip/ip4_addr.h"

struct netif {
  ip4_addr_t ip_addr;
  ip4_addr_t netmask;
  ip4_addr_t gw;
};

#ifdef __cplusplus
extern "C" {
#endif
extern struct netif* netif_default;
#ifdef __cplusplus
}
#endif

#endif  // MROS2_PC_LWIP_NETIF_H
