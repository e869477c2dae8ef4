// SPDX-License-Identifier: BSD-3-Clause
// lwIP's tcpip thread (lwip/tcpip.h): one lock, the core lock, keeps other
// threads' raw API calls apart from it, as with LWIP_TCPIP_CORE_LOCKING.
#ifndef MROS2_PC_LWIP_TCPIP_H
#define MROS2_PC_LWIP_TCPIP_H

#include "lwip/netif.h"
#include "lwip/pbuf.h"
#include "lwip/sys.h"

#ifdef __cplusplus
extern "C" {
#endif
void sys_lock_tcpip_core(void);
void sys_unlock_tcpip_core(void);
#ifdef __cplusplus
}
#endif

#define LOCK_TCPIP_CORE() sys_lock_tcpip_core()
#define UNLOCK_TCPIP_CORE() sys_unlock_tcpip_core()

#endif  // MROS2_PC_LWIP_TCPIP_H
