/* SPDX-License-Identifier: BSD-3-Clause */
/* lwIP's DHCP client on a PC: the "lease" is the PC's address for ROS. */
#ifndef MROS_PC_TARGET_LWIP_DHCP_H
#define MROS_PC_TARGET_LWIP_DHCP_H

#include "lwip/netif.h"

#ifdef __cplusplus
extern "C" {
#endif

err_t dhcp_start(struct netif *netif);

#ifdef __cplusplus
}
#endif

#endif /* MROS_PC_TARGET_LWIP_DHCP_H */
