// SPDX-License-Identifier: BSD-3-Clause
// mros2-posix' way for an app to give the board its address
// (netif_posix_add.h): here the address must be the board side's of
// genmros mros2-pc's network, which the program checks.
#ifndef MROS2_PC_NETIF_POSIX_ADD_H
#define MROS2_PC_NETIF_POSIX_ADD_H

#ifdef __cplusplus
extern "C" {
#endif
int netif_posix_add(const char* ipaddr, const char* netmask);
#ifdef __cplusplus
}
#endif

#endif  // MROS2_PC_NETIF_POSIX_ADD_H
