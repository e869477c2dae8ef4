/* SPDX-License-Identifier: BSD-3-Clause */
/* lwIP's name lookup on a PC: dotted quads, "localhost" and /etc/hosts
 * (no DNS, as a static binary's lookup without NSS). */
#ifndef MROS_PC_TARGET_LWIP_NETDB_H
#define MROS_PC_TARGET_LWIP_NETDB_H

#include <netdb.h>

#ifdef __cplusplus
extern "C" {
#endif

struct hostent *lwip_gethostbyname(const char *name);

#ifdef __cplusplus
}
#endif

#endif /* MROS_PC_TARGET_LWIP_NETDB_H */
