/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * lwIP on a PC: its socket calls on the host's sockets, its network
 * interface and DHCP client standing for the PC's own address. Every socket
 * call is a host call (pc_target.h): the task gives up the CPU and takes it
 * back in priority order, as it waits for lwIP's tcpip thread on the board.
 * Host calls and name lookups run on the task thread's host stack: they
 * are the host's, not the board's lwIP.
 */
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include "lwip/dhcp.h"
#include "lwip/inet.h"
#include "lwip/init.h"
#include "lwip/netdb.h"
#include "lwip/netif.h"
#include "lwip/sockets.h"
#include "lwip/tcpip.h"
#include "eth_arch.h"
#include "pc_target.h"

namespace {

template <typename Work>
void do_work(void *work) {
  (*static_cast<Work *>(work))();
}

// Does work() on the calling task thread's host stack.
template <typename Work>
void on_host_stack(Work work) {
  pc_on_host_stack(do_work<Work>, &work);
}

// A host call: the task gives up the CPU while call() runs on its thread's
// host stack, and the host's errno comes back with the result.
template <typename Call>
int host_call(Call call) {
  int result = 0;
  int host_errno = 0;
  on_host_stack([&] {
    pc_host_call_begin();
    result = call();
    host_errno = errno;
    pc_host_call_end();
  });
  errno = host_errno;
  return result;
}

}  // namespace

int lwip_accept(int s, struct sockaddr *addr, socklen_t *addrlen) {
  return host_call([&] { return accept(s, addr, addrlen); });
}

/* The slave and publisher ports are fixed; a PC restarts the node far more
 * often than a board, and a port in TIME_WAIT must not stop it. The board has
 * one address: a port bound to any address takes connections to the node's
 * address only, as on the board, where 127.0.0.1 never reaches it (else a
 * publisherUpdate naming 127.0.0.1 and its own slave port would make the
 * slave call itself, which no board can). */
int lwip_bind(int s, const struct sockaddr *name, socklen_t namelen) {
  int reuse = 1;
  setsockopt(s, SOL_SOCKET, SO_REUSEADDR, &reuse, sizeof reuse);
  struct sockaddr_in node;
  if (name->sa_family == AF_INET && namelen >= sizeof node) {
    memcpy(&node, name, sizeof node);
    if (node.sin_addr.s_addr == htonl(INADDR_ANY)) {
      inet_pton(AF_INET, pc_node_address(), &node.sin_addr);
      return host_call(
          [&] { return bind(s, reinterpret_cast<struct sockaddr *>(&node), sizeof node); });
    }
  }
  return host_call([&] { return bind(s, name, namelen); });
}

int lwip_shutdown(int s, int how) { return host_call([&] { return shutdown(s, how); }); }

int lwip_getpeername(int s, struct sockaddr *name, socklen_t *namelen) {
  return host_call([&] { return getpeername(s, name, namelen); });
}

int lwip_getsockname(int s, struct sockaddr *name, socklen_t *namelen) {
  return host_call([&] { return getsockname(s, name, namelen); });
}

int lwip_getsockopt(int s, int level, int optname, void *optval, socklen_t *optlen) {
  return host_call([&] { return getsockopt(s, level, optname, optval, optlen); });
}

/* lwIP 1.4, the one mbed 2 ships, takes SO_RCVTIMEO and SO_SNDTIMEO as an int
 * of milliseconds; the host takes a struct timeval. */
int lwip_setsockopt(int s, int level, int optname, const void *optval, socklen_t optlen) {
  struct timeval host_timeout;
  if (level == SOL_SOCKET && (optname == SO_RCVTIMEO || optname == SO_SNDTIMEO) &&
      optlen == sizeof(int)) {
    int milliseconds;
    memcpy(&milliseconds, optval, sizeof milliseconds);
    host_timeout.tv_sec = milliseconds / 1000;
    host_timeout.tv_usec = (milliseconds % 1000) * 1000;
    optval = &host_timeout;
    optlen = sizeof host_timeout;
  }
  return host_call([&] { return setsockopt(s, level, optname, optval, optlen); });
}

int lwip_close(int s) { return host_call([&] { return close(s); }); }

int lwip_connect(int s, const struct sockaddr *name, socklen_t namelen) {
  return host_call([&] { return connect(s, name, namelen); });
}

int lwip_listen(int s, int backlog) { return host_call([&] { return listen(s, backlog); }); }

int lwip_recv(int s, void *mem, size_t len, int flags) {
  return host_call([&] { return (int)recv(s, mem, len, flags); });
}

int lwip_read(int s, void *mem, size_t len) {
  return host_call([&] { return (int)read(s, mem, len); });
}

int lwip_recvfrom(int s, void *mem, size_t len, int flags, struct sockaddr *from,
                  socklen_t *fromlen) {
  return host_call([&] { return (int)recvfrom(s, mem, len, flags, from, fromlen); });
}

/* A peer that has gone away gives an error, not SIGPIPE. */
int lwip_send(int s, const void *dataptr, size_t size, int flags) {
  return host_call([&] { return (int)send(s, dataptr, size, flags | MSG_NOSIGNAL); });
}

int lwip_sendto(int s, const void *dataptr, size_t size, int flags, const struct sockaddr *to,
                socklen_t tolen) {
  return host_call(
      [&] { return (int)sendto(s, dataptr, size, flags | MSG_NOSIGNAL, to, tolen); });
}

int lwip_socket(int domain, int type, int protocol) {
  return host_call([&] { return socket(domain, type, protocol); });
}

int lwip_write(int s, const void *dataptr, size_t size) {
  return host_call([&] { return (int)send(s, dataptr, size, MSG_NOSIGNAL); });
}

int lwip_select(int maxfdp1, fd_set *readset, fd_set *writeset, fd_set *exceptset,
                struct timeval *timeout) {
  return host_call([&] { return select(maxfdp1, readset, writeset, exceptset, timeout); });
}

int lwip_ioctl(int s, long cmd, void *argp) {
  return host_call([&] { return ioctl(s, (unsigned long)cmd, argp); });
}

int lwip_fcntl(int s, int cmd, int val) { return host_call([&] { return fcntl(s, cmd, val); }); }

void lwip_init(void) {}

/* ---- names and addresses ---- */

char *ipaddr_ntoa(const ip_addr_t *addr) {
  static char text[16];
  const unsigned char *bytes = reinterpret_cast<const unsigned char *>(&addr->addr);
  snprintf(text, sizeof text, "%u.%u.%u.%u", bytes[0], bytes[1], bytes[2], bytes[3]);
  return text;
}

int ipaddr_aton(const char *text, ip_addr_t *addr) {
  struct in_addr host;
  if (inet_pton(AF_INET, text, &host) != 1) return 0;
  if (addr != NULL) addr->addr = host.s_addr;
  return 1;
}

/* The IPv4 address of name from /etc/hosts, as the board has no DNS either. */
static int address_from_hosts(const char *name, ip_addr_t *address) {
  char line[512];
  int found = 0;
  FILE *hosts = fopen("/etc/hosts", "r");
  if (hosts == NULL) return 0;
  while (!found && fgets(line, sizeof line, hosts) != NULL) {
    char *rest = NULL;
    char *field = strtok_r(line, " \t\r\n", &rest);
    ip_addr_t candidate;
    if (field == NULL || field[0] == '#' || !ipaddr_aton(field, &candidate)) continue;
    while (!found && (field = strtok_r(NULL, " \t\r\n", &rest)) != NULL && field[0] != '#') {
      if (strcasecmp(field, name) == 0) {
        *address = candidate;
        found = 1;
      }
    }
  }
  fclose(hosts);
  return found;
}

static int address_of(const char *name, ip_addr_t *address) {
  if (ipaddr_aton(name, address)) return 1;
  if (strcasecmp(name, "localhost") == 0) return ipaddr_aton("127.0.0.1", address);
  return address_from_hosts(name, address);
}

struct hostent *lwip_gethostbyname(const char *name) {
  static ip_addr_t address;
  static char *addresses[2];
  static struct hostent entry;
  int found = 0;
  on_host_stack([&] { found = address_of(name, &address); });
  if (!found) return NULL;
  addresses[0] = reinterpret_cast<char *>(&address.addr);
  addresses[1] = NULL;
  entry.h_name = const_cast<char *>(name);
  entry.h_aliases = NULL;
  entry.h_addrtype = AF_INET;
  entry.h_length = 4;
  entry.h_addr_list = addresses;
  return &entry;
}

static void unusable(const char *variable, const char *value) {
  fprintf(stderr, "mROS PC target: %s=%s: not an IPv4 address or a name in /etc/hosts\n",
          variable, value);
  exit(2);
}

static void find_node_address(char *text, size_t size) {
  const char *ros_ip = getenv("ROS_IP");
  const char *ros_hostname = getenv("ROS_HOSTNAME");
  ip_addr_t address;
  if (ros_ip != NULL && ros_ip[0] != '\0') {
    if (!ipaddr_aton(ros_ip, &address)) unusable("ROS_IP", ros_ip);
  } else if (ros_hostname != NULL && ros_hostname[0] != '\0') {
    if (!address_of(ros_hostname, &address)) unusable("ROS_HOSTNAME", ros_hostname);
  } else {
    ipaddr_aton("127.0.0.1", &address);
  }
  snprintf(text, size, "%s", ipaddr_ntoa(&address));
}

const char *pc_node_address(void) {
  static char text[16];
  if (text[0] == '\0') on_host_stack([&] { find_node_address(text, sizeof text); });
  return text;
}

/* ---- the network interface ---- */

static void bring_up(struct netif *netif) {
  netif->flags |= NETIF_FLAG_UP | NETIF_FLAG_LINK_UP;
  if (netif->link_callback != NULL) netif->link_callback(netif);
  if (netif->status_callback != NULL) netif->status_callback(netif);
}

struct netif *netif_add(struct netif *netif, ip_addr_t *ipaddr, ip_addr_t *netmask,
                        ip_addr_t *gw, void *state, netif_init_fn init, netif_input_fn input) {
  (void)ipaddr;
  (void)input;
  /* The address the app configured is the board's; on the PC it is the PC's. */
  ipaddr_aton(pc_node_address(), &netif->ip_addr);
  netif->netmask.addr = netmask != NULL ? netmask->addr : htonl(0xff000000u);
  netif->gw.addr = gw != NULL ? gw->addr : 0;
  netif->state = state;
  if (init != NULL) init(netif);
  return netif;
}

void netif_set_default(struct netif *netif) { (void)netif; }

void netif_set_up(struct netif *netif) { bring_up(netif); }

void netif_set_status_callback(struct netif *netif, netif_status_callback_fn callback) {
  netif->status_callback = callback;
}

void netif_set_link_callback(struct netif *netif, netif_status_callback_fn callback) {
  netif->link_callback = callback;
}

err_t dhcp_start(struct netif *netif) {
  bring_up(netif);
  return ERR_OK;
}

void tcpip_init(tcpip_init_done_fn initfunc, void *arg) {
  if (initfunc != NULL) initfunc(arg);
}

err_t tcpip_input(struct pbuf *p, struct netif *inp) {
  (void)p;
  (void)inp;
  return ERR_OK;
}

err_t eth_arch_enetif_init(struct netif *netif) {
  (void)netif;
  return ERR_OK;
}

void eth_arch_enable_interrupts(void) {}

void eth_arch_disable_interrupts(void) {}
