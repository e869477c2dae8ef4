/* SPDX-License-Identifier: BSD-3-Clause */
/* lwIP's initialisation on a PC: the host's network stack needs none. */
#ifndef MROS_PC_TARGET_LWIP_INIT_H
#define MROS_PC_TARGET_LWIP_INIT_H

#ifdef __cplusplus
extern "C" {
#endif

void lwip_init(void);

#ifdef __cplusplus
}
#endif

#endif /* MROS_PC_TARGET_LWIP_INIT_H */
