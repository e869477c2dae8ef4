/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * lwIP's BSD-style socket API on a PC: each lwip_* call is the host's socket
 * call of the same name. The calling task gives up the CPU for the call, as
 * an ASP task does while lwIP's tcpip thread serves it, so other tasks run
 * while it blocks (see pc_target.h).
 */
#ifndef MROS_PC_TARGET_LWIP_SOCKETS_H
#define MROS_PC_TARGET_LWIP_SOCKETS_H

#include <string.h>
#include <sys/select.h>
#include <sys/socket.h>
#include <sys/time.h>
#include <netinet/in.h>
#include <netinet/tcp.h>

#include "lwip/ip_addr.h"

/* lwIP's FD_ZERO names no type; glibc's names fd_set, which mROS v1 also
 * uses as the name of a variable (mros_comm_socket_cimpl.c). */
#undef FD_ZERO
#define FD_ZERO(set) memset((set), 0, sizeof(*(set)))

#ifdef __cplusplus
extern "C" {
#endif

int lwip_accept(int s, struct sockaddr *addr, socklen_t *addrlen);
int lwip_bind(int s, const struct sockaddr *name, socklen_t namelen);
int lwip_shutdown(int s, int how);
int lwip_getpeername(int s, struct sockaddr *name, socklen_t *namelen);
int lwip_getsockname(int s, struct sockaddr *name, socklen_t *namelen);
int lwip_getsockopt(int s, int level, int optname, void *optval, socklen_t *optlen);
int lwip_setsockopt(int s, int level, int optname, const void *optval, socklen_t optlen);
int lwip_close(int s);
int lwip_connect(int s, const struct sockaddr *name, socklen_t namelen);
int lwip_listen(int s, int backlog);
int lwip_recv(int s, void *mem, size_t len, int flags);
int lwip_read(int s, void *mem, size_t len);
int lwip_recvfrom(int s, void *mem, size_t len, int flags, struct sockaddr *from,
                  socklen_t *fromlen);
int lwip_send(int s, const void *dataptr, size_t size, int flags);
int lwip_sendto(int s, const void *dataptr, size_t size, int flags, const struct sockaddr *to,
                socklen_t tolen);
int lwip_socket(int domain, int type, int protocol);
int lwip_write(int s, const void *dataptr, size_t size);
int lwip_select(int maxfdp1, fd_set *readset, fd_set *writeset, fd_set *exceptset,
                struct timeval *timeout);
int lwip_ioctl(int s, long cmd, void *argp);
int lwip_fcntl(int s, int cmd, int val);

#ifdef __cplusplus
}
#endif

#endif /* MROS_PC_TARGET_LWIP_SOCKETS_H */
