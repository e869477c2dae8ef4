/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * lwIP's network interface on a PC. The board's Ethernet interface gets its
 * address from DHCP or from mros_sys_config.h; here it gets the PC's address
 * for ROS (ROS_IP, else ROS_HOSTNAME, else 127.0.0.1) and is up at once.
 */
#ifndef MROS_PC_TARGET_LWIP_NETIF_H
#define MROS_PC_TARGET_LWIP_NETIF_H

#include <stdint.h>

#include "lwip/ip_addr.h"

#ifdef __cplusplus
extern "C" {
#endif

struct pbuf;
struct netif;
typedef err_t (*netif_init_fn)(struct netif *netif);
typedef err_t (*netif_input_fn)(struct pbuf *p, struct netif *inp);
typedef void (*netif_status_callback_fn)(struct netif *netif);

#define NETIF_FLAG_UP 0x01U
#define NETIF_FLAG_LINK_UP 0x10U

struct netif {
  ip_addr_t ip_addr;
  ip_addr_t netmask;
  ip_addr_t gw;
  uint8_t flags;
  netif_status_callback_fn status_callback;
  netif_status_callback_fn link_callback;
  void *state;
};

struct netif *netif_add(struct netif *netif, ip_addr_t *ipaddr, ip_addr_t *netmask,
                        ip_addr_t *gw, void *state, netif_init_fn init, netif_input_fn input);
void netif_set_default(struct netif *netif);
void netif_set_up(struct netif *netif);
void netif_set_status_callback(struct netif *netif, netif_status_callback_fn callback);
void netif_set_link_callback(struct netif *netif, netif_status_callback_fn callback);
#define netif_is_up(netif) (((netif)->flags & NETIF_FLAG_UP) != 0)
#define netif_is_link_up(netif) (((netif)->flags & NETIF_FLAG_LINK_UP) != 0)

/* The PC's address for ROS, as a dotted quad. */
const char *pc_node_address(void);

#ifdef __cplusplus
}
#endif

#endif /* MROS_PC_TARGET_LWIP_NETIF_H */
