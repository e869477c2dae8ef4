// SPDX-License-Identifier: BSD-3-Clause
// lwIP's IPv4 address (lwip/ip4_addr.h, lwip/ip_addr.h with IPv4 only):
// the address in network byte order, and the tests embeddedRTPS uses.
#ifndef MROS2_PC_LWIP_IP4_ADDR_H
#define MROS2_PC_LWIP_IP4_ADDR_H

#include "lwip/arch.h"

struct ip4_addr {
  u32_t addr;
};
typedef struct ip4_addr ip4_addr_t;
typedef ip4_addr_t ip_addr_t;

#ifdef __cplusplus
extern "C" {
#endif
extern const ip_addr_t ip_addr_any;
// The address as text (a.b.c.d), in a buffer the next call overwrites.
char* ip4addr_ntoa(const ip4_addr_t* address);
#ifdef __cplusplus
}
#endif
#define IP_ADDR_ANY (&ip_addr_any)
#define IP4_ADDR_ANY (&ip_addr_any)

// The address's bytes in the order they are written (a.b.c.d).
static inline u8_t ip4_addr_byte(const ip4_addr_t* address, int index) {
  return ((const u8_t*)&address->addr)[index];
}
#define ip4_addr1(address) ip4_addr_byte(address, 0)
#define ip4_addr2(address) ip4_addr_byte(address, 1)
#define ip4_addr3(address) ip4_addr_byte(address, 2)
#define ip4_addr4(address) ip4_addr_byte(address, 3)

static inline int ip4_addr_cmp(const ip4_addr_t* a, const ip4_addr_t* b) {
  return a->addr == b->addr;
}
static inline int ip4_addr_netcmp(const ip4_addr_t* a, const ip4_addr_t* b,
                                  const ip4_addr_t* mask) {
  return (a->addr & mask->addr) == (b->addr & mask->addr);
}
// 224.0.0.0/4, whatever the host's byte order.
static inline int ip4_addr_ismulticast(const ip4_addr_t* address) {
  return (ip4_addr1(address) & 0xf0) == 0xe0;
}

#endif  // MROS2_PC_LWIP_IP4_ADDR_H
