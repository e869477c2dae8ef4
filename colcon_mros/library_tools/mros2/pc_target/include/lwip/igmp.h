// SPDX-License-Identifier: BSD-3-Clause
// lwIP's IGMP (lwip/igmp.h): the board's interface joins a multicast group.
#ifndef MROS2_PC_LWIP_IGMP_H
#define MROS2_PC_LWIP_IGMP_H

#include "lwip/err.h"
#include "lwip/ip4_addr.h"

#ifdef __cplusplus
extern "C" {
#endif
err_t igmp_joingroup(const ip4_addr_t* interface_address, const ip4_addr_t* group);
#ifdef __cplusplus
}
#endif

#endif  // MROS2_PC_LWIP_IGMP_H
