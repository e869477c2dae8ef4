/* SPDX-License-Identifier: BSD-3-Clause */
/* lwIP's IPv4 address type on a PC (lwIP 1.4's layout: network order). */
#ifndef MROS_PC_TARGET_LWIP_IP_ADDR_H
#define MROS_PC_TARGET_LWIP_IP_ADDR_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct ip_addr {
  uint32_t addr;
} ip_addr_t;

typedef int8_t err_t;
#define ERR_OK 0

char *ipaddr_ntoa(const ip_addr_t *addr);
int ipaddr_aton(const char *text, ip_addr_t *addr);

#ifdef __cplusplus
}
#endif

#endif /* MROS_PC_TARGET_LWIP_IP_ADDR_H */
