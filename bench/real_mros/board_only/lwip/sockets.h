/* SPDX-License-Identifier: BSD-3-Clause */
/* Stand-in for lwIP's socket API: the types mROS v1's headers name. */
#ifndef STUB_LWIP_SOCKETS_H
#define STUB_LWIP_SOCKETS_H
#include <stdint.h>
struct sockaddr { uint8_t sa_len; uint8_t sa_family; char sa_data[14]; };
struct in_addr { uint32_t s_addr; };
struct sockaddr_in { uint8_t sin_len; uint8_t sin_family; uint16_t sin_port; struct in_addr sin_addr; char sin_zero[8]; };
struct timeval { long tv_sec; long tv_usec; };
typedef struct { unsigned char fd_bits[8]; } fd_set;
typedef struct { uint32_t addr; } ip_addr_t;
#define FD_SETSIZE 64
#define FD_ZERO(set) ((void)(set))
#define FD_SET(n, set) ((void)(n), (void)(set))
#define FD_ISSET(n, set) ((void)(n), (void)(set), 0)
#define SOCK_STREAM 1
#define SOCK_DGRAM 2
#define SOCK_RAW 3
#define AF_UNSPEC 0
#define AF_INET 2
/* recv's flags, valued as in lwIP 1.4's sockets.h. */
#define MSG_PEEK 0x01
#define MSG_DONTWAIT 0x08
#endif
