// SPDX-License-Identifier: BSD-3-Clause
// mros2-posix' netif.h: the board's address and netmask, here those of the
// board side of genmros mros2-pc's network (mros2_pc_settings.h).
#ifndef MROS2_PC_NETIF_H
#define MROS2_PC_NETIF_H

#include "mros2_pc_settings.h"

#define NETIF_IPADDR MROS2_PC_BOARD_ADDRESS
#define NETIF_NETMASK MROS2_PC_BOARD_NETMASK

#endif  // MROS2_PC_NETIF_H
