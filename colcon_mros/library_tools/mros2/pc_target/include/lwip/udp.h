// SPDX-License-Identifier: BSD-3-Clause
// lwIP's raw UDP API (lwip/udp.h). Call it holding the tcpip core lock, as
// on the board; receive callbacks run on the tcpip thread, which holds it.
#ifndef MROS2_PC_LWIP_UDP_H
#define MROS2_PC_LWIP_UDP_H

#include "lwip/ip4_addr.h"
#include "lwip/netif.h"
#include "lwip/pbuf.h"

struct udp_pcb;
typedef void (*udp_recv_fn)(void* arg, struct udp_pcb* pcb, struct pbuf* p,
                            const ip_addr_t* addr, u16_t port);

struct udp_pcb {
  u16_t local_port;
  udp_recv_fn recv;
  void* recv_arg;
  int socket;  // the host's UDP socket
  struct udp_pcb* next;
};

#ifdef __cplusplus
extern "C" {
#endif
struct udp_pcb* udp_new(void);
void udp_remove(struct udp_pcb* pcb);
err_t udp_bind(struct udp_pcb* pcb, const ip_addr_t* address, u16_t port);
void udp_recv(struct udp_pcb* pcb, udp_recv_fn recv, void* recv_arg);
err_t udp_sendto(struct udp_pcb* pcb, struct pbuf* p, const ip_addr_t* destination,
                 u16_t port);
#ifdef __cplusplus
}
#endif

#endif  // MROS2_PC_LWIP_UDP_H
