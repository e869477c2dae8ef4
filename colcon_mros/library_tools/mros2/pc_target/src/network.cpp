// SPDX-License-Identifier: BSD-3-Clause
// The board's network on host UDP sockets: lwIP's raw UDP API, IGMP joins,
// the tcpip thread with its core lock, the interface, and the start-up
// calls MX_LWIP_Init and netif_posix_add.
//
// Each udp_pcb is a non-blocking host socket. The tcpip thread waits on all
// of them and, holding the core lock, hands each datagram to its pcb's
// receive callback in a pbuf, as lwIP's tcpip thread does. A datagram over
// the board's receive limit (MROS2_PC_RECEIVE_LIMIT, genmros mros2-pc
// --receive-limit) is cut to it, as mros2-posix' lwIP cuts it, and reported
// by a host thread of its own (on the arm target the tcpip thread runs on the
// board's stack size, which the C library's formatting would overflow and
// blame on the board). Multicast sent is not looped back to the board, as
// lwIP does by default.
#include <arpa/inet.h>
#include <errno.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <poll.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <unistd.h>

#include <array>
#include <vector>

#include "board_threads.h"
#include "lwip.h"
#include "lwip/igmp.h"
#include "lwip/tcpip.h"
#include "lwip/udp.h"
#include "mros2_pc_settings.h"
#include "netif_posix_add.h"

#ifdef MROS2_PC_SETS_RTPS_ADDRESS
// mros2 >= 0.5 defines the address embeddedRTPS announces (mros2.h).
namespace rtps {
namespace Config {
extern std::array<uint8_t, 4> IP_ADDRESS;
}
}  // namespace rtps
#endif

extern "C" {
const ip_addr_t ip_addr_any = {0};
struct netif* netif_default = NULL;
}

namespace {

struct netif board_netif;
pthread_mutex_t core_lock = PTHREAD_MUTEX_INITIALIZER;
udp_pcb* pcbs;                     // under the core lock
std::vector<int> sockets_to_close;  // under the core lock
int wake_pipe[2] = {-1, -1};
int membership_socket = -1;
unsigned long cut_datagrams;
// The tcpip thread writes a CutDatagram here for the reporter to print.
int report_pipe[2] = {-1, -1};

struct CutDatagram {
  ssize_t length;
  struct sockaddr_in from;
  unsigned long so_far;
};

void* report_cut_datagrams(void*) {
  CutDatagram cut;
  while (read(report_pipe[0], &cut, sizeof cut) == (ssize_t)sizeof cut) {
    fprintf(stderr,
            "mros2 PC target: a datagram of %zd bytes from %s:%u was cut to the board's "
            "receive limit of %u bytes (%lu so far)\n",
            cut.length, inet_ntoa(cut.from.sin_addr), ntohs(cut.from.sin_port),
            (unsigned)MROS2_PC_RECEIVE_LIMIT, cut.so_far);
  }
  return NULL;
}

// Makes the tcpip thread take a new set of sockets.
void wake_tcpip_thread() {
  if (wake_pipe[1] >= 0 && write(wake_pipe[1], "", 1) < 0 && errno != EAGAIN) {
    mros2_pc::stop("cannot wake the tcpip thread");
  }
}

in_addr_t parsed_address(const char* text, const char* what) {
  struct in_addr address;
  if (inet_pton(AF_INET, text, &address) != 1) {
    fprintf(stderr, "mros2 PC target: %s '%s' is no IPv4 address\n", what, text);
    exit(2);
  }
  return address.s_addr;
}

void deliver(udp_pcb* pcb, const unsigned char* bytes, size_t length,
             const struct sockaddr_in& from) {
  struct pbuf* p = pbuf_alloc(PBUF_TRANSPORT, (u16_t)length, PBUF_POOL);
  if (p == NULL) return;  // as lwIP drops a datagram when its pool is empty
  memcpy(p->payload, bytes, length);
  if (pcb->recv == NULL) {
    pbuf_free(p);
    return;
  }
  ip_addr_t address = {from.sin_addr.s_addr};
  pcb->recv(pcb->recv_arg, pcb, p, &address, ntohs(from.sin_port));
}

// Reads what waits on socket, cut at the receive limit, for its pcb.
void receive_all(int socket) {
  static unsigned char datagram[MROS2_PC_RECEIVE_LIMIT];
  for (;;) {
    struct sockaddr_in from;
    socklen_t from_length = sizeof from;
    ssize_t length = recvfrom(socket, datagram, sizeof datagram, MSG_TRUNC,
                              (struct sockaddr*)&from, &from_length);
    if (length < 0) return;  // EAGAIN: all read
    if ((size_t)length > sizeof datagram) {
      if (cut_datagrams++ % 1000 == 0) {
        CutDatagram cut = {length, from, cut_datagrams};
        // A full pipe loses the report, never the board's time.
        if (write(report_pipe[1], &cut, sizeof cut) < 0 && errno != EAGAIN) {
          mros2_pc::stop("cannot report a cut datagram");
        }
      }
      length = (ssize_t)sizeof datagram;
    }
    for (udp_pcb* pcb = pcbs; pcb != NULL; pcb = pcb->next) {
      if (pcb->socket == socket) {
        deliver(pcb, datagram, (size_t)length, from);
        break;
      }
    }
  }
}

void tcpip_thread(void*) {
  std::vector<struct pollfd> waiting;
  for (;;) {
    waiting.clear();
    waiting.push_back({wake_pipe[0], POLLIN, 0});
    sys_lock_tcpip_core();
    for (int socket : sockets_to_close) close(socket);
    sockets_to_close.clear();
    for (udp_pcb* pcb = pcbs; pcb != NULL; pcb = pcb->next) {
      if (pcb->local_port != 0) waiting.push_back({pcb->socket, POLLIN, 0});
    }
    sys_unlock_tcpip_core();
    if (poll(waiting.data(), waiting.size(), -1) < 0) continue;  // EINTR
    char drained[64];
    while (read(wake_pipe[0], drained, sizeof drained) > 0) {
    }
    sys_lock_tcpip_core();
    for (size_t index = 1; index < waiting.size(); index++) {
      if (waiting[index].revents & POLLIN) receive_all(waiting[index].fd);
    }
    sys_unlock_tcpip_core();
  }
}

err_t socket_error(int error) {
  if (error == ENETUNREACH || error == EHOSTUNREACH) return ERR_RTE;
  if (error == ENOBUFS || error == ENOMEM) return ERR_MEM;
  return ERR_VAL;
}

}  // namespace

extern "C" {

char* ip4addr_ntoa(const ip4_addr_t* address) {
  static char text[INET_ADDRSTRLEN];
  struct in_addr host_address = {address->addr};
  return inet_ntop(AF_INET, &host_address, text, sizeof text) != NULL ? text : NULL;
}

void sys_lock_tcpip_core(void) { pthread_mutex_lock(&core_lock); }

void sys_unlock_tcpip_core(void) { pthread_mutex_unlock(&core_lock); }

int netif_posix_add(const char* ipaddr, const char* netmask) {
  in_addr_t address = parsed_address(ipaddr, "netif_posix_add: the address");
  if (address != parsed_address(MROS2_PC_BOARD_ADDRESS, "the board side's address")) {
    fprintf(stderr,
            "mros2 PC target: netif_posix_add gives the board %s, but the board side of genmros "
            "mros2-pc's network is %s: give genmros mros2-pc --board-address %s\n",
            ipaddr, MROS2_PC_BOARD_ADDRESS, ipaddr);
    exit(2);
  }
  board_netif.ip_addr.addr = address;
  board_netif.netmask.addr = parsed_address(netmask, "netif_posix_add: the netmask");
  return 0;
}

void MX_LWIP_Init(void) {
  if (board_netif.ip_addr.addr == 0) {
    netif_posix_add(MROS2_PC_BOARD_ADDRESS, MROS2_PC_BOARD_NETMASK);
  }
  netif_default = &board_netif;
#ifdef MROS2_PC_SETS_RTPS_ADDRESS
  memcpy(rtps::Config::IP_ADDRESS.data(), &board_netif.ip_addr.addr, 4);
#endif
  if (pipe2(wake_pipe, O_NONBLOCK | O_CLOEXEC) != 0 || pipe2(report_pipe, O_CLOEXEC) != 0 ||
      fcntl(report_pipe[1], F_SETFL, O_NONBLOCK) != 0) {
    mros2_pc::stop("cannot make the tcpip thread's pipes");
  }
  pthread_t reporter;
  if (pthread_create(&reporter, NULL, report_cut_datagrams, NULL) != 0 ||
      pthread_detach(reporter) != 0) {
    mros2_pc::stop("cannot start the reporter of cut datagrams");
  }
  mros2_pc::start_thread("tcpip_thread", tcpip_thread, NULL, MROS2_PC_TCPIP_STACK_SIZE);
}

struct udp_pcb* udp_new(void) {
  int made = socket(AF_INET, SOCK_DGRAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
  if (made < 0) return NULL;
  struct in_addr interface_address = {board_netif.ip_addr.addr};
  unsigned char no = 0;
  setsockopt(made, IPPROTO_IP, IP_MULTICAST_IF, &interface_address, sizeof interface_address);
  setsockopt(made, IPPROTO_IP, IP_MULTICAST_LOOP, &no, sizeof no);
  udp_pcb* pcb = new udp_pcb();
  pcb->socket = made;
  pcb->next = pcbs;
  pcbs = pcb;
  return pcb;
}

void udp_remove(struct udp_pcb* pcb) {
  for (udp_pcb** link = &pcbs; *link != NULL; link = &(*link)->next) {
    if (*link == pcb) {
      *link = pcb->next;
      break;
    }
  }
  // The tcpip thread may be waiting on the socket: it closes it.
  sockets_to_close.push_back(pcb->socket);
  delete pcb;
  wake_tcpip_thread();
}

err_t udp_bind(struct udp_pcb* pcb, const ip_addr_t* address, u16_t port) {
  struct sockaddr_in local;
  memset(&local, 0, sizeof local);
  local.sin_family = AF_INET;
  local.sin_addr.s_addr = address != NULL ? address->addr : INADDR_ANY;
  local.sin_port = htons(port);
  if (bind(pcb->socket, (struct sockaddr*)&local, sizeof local) != 0) {
    return errno == EADDRINUSE ? ERR_USE : ERR_VAL;
  }
  pcb->local_port = port;
  wake_tcpip_thread();
  return ERR_OK;
}

void udp_recv(struct udp_pcb* pcb, udp_recv_fn recv, void* recv_arg) {
  pcb->recv = recv;
  pcb->recv_arg = recv_arg;
}

err_t udp_sendto(struct udp_pcb* pcb, struct pbuf* p, const ip_addr_t* destination,
                 u16_t port) {
  std::vector<unsigned char> datagram;
  datagram.reserve(p->tot_len);
  for (struct pbuf* part = p; part != NULL; part = part->next) {
    const unsigned char* bytes = static_cast<const unsigned char*>(part->payload);
    datagram.insert(datagram.end(), bytes, bytes + part->len);
  }
  struct sockaddr_in to;
  memset(&to, 0, sizeof to);
  to.sin_family = AF_INET;
  to.sin_addr.s_addr = destination->addr;
  to.sin_port = htons(port);
  if (sendto(pcb->socket, datagram.data(), datagram.size(), 0, (struct sockaddr*)&to,
             sizeof to) < 0) {
    return socket_error(errno);
  }
  return ERR_OK;
}

err_t igmp_joingroup(const ip4_addr_t*, const ip4_addr_t* group) {
  // Sockets bound to the group's port take its datagrams once the
  // interface has joined it; one socket holds every membership.
  if (membership_socket < 0) {
    membership_socket = socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
    if (membership_socket < 0) return ERR_MEM;
  }
  struct ip_mreq request;
  request.imr_multiaddr.s_addr = group->addr;
  request.imr_interface.s_addr = board_netif.ip_addr.addr;
  if (setsockopt(membership_socket, IPPROTO_IP, IP_ADD_MEMBERSHIP, &request, sizeof request) != 0) {
    return errno == EADDRINUSE ? ERR_OK : ERR_VAL;  // already a member
  }
  return ERR_OK;
}

}  // extern "C"
