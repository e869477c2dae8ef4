/* SPDX-License-Identifier: BSD-3-Clause */
/* lwIP's address conversions on a PC, taking ip_addr_t as lwIP 1.4's do. */
#ifndef MROS_PC_TARGET_LWIP_INET_H
#define MROS_PC_TARGET_LWIP_INET_H

#include <arpa/inet.h>

#include "lwip/ip_addr.h"

#undef inet_ntoa
#undef inet_aton
#define inet_ntoa(addr) ipaddr_ntoa((const ip_addr_t *)&(addr))
#define inet_aton(text, addr) ipaddr_aton((text), (ip_addr_t *)(addr))

#endif /* MROS_PC_TARGET_LWIP_INET_H */
