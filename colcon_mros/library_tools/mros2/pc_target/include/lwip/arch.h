// SPDX-License-Identifier: BSD-3-Clause
// lwIP's sized integer names (lwip/arch.h), as the board's port defines them.
#ifndef MROS2_PC_LWIP_ARCH_H
#define MROS2_PC_LWIP_ARCH_H

#include <stddef.h>
#include <stdint.h>

typedef uint8_t u8_t;
typedef int8_t s8_t;
typedef uint16_t u16_t;
typedef int16_t s16_t;
typedef uint32_t u32_t;
typedef int32_t s32_t;

#define LWIP_UNUSED_ARG(x) (void)(x)

#endif  // MROS2_PC_LWIP_ARCH_H
