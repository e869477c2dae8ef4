/* SPDX-License-Identifier: BSD-3-Clause */
/* TOPPERS/ASP's t_stdlib.h on a PC: the C library's own functions. */
#ifndef MROS_PC_TARGET_T_STDLIB_H
#define MROS_PC_TARGET_T_STDLIB_H
#include <stdlib.h>
#include <string.h>
#endif /* MROS_PC_TARGET_T_STDLIB_H */
