/* SPDX-License-Identifier: BSD-3-Clause */
/* TOPPERS/ASP's syssvc/serial.h on a PC: nothing to declare (the log goes
 * to stderr through syslog() in t_syslog.h; there is no serial port). */
#ifndef MROS_PC_TARGET_SYSSVC_SERIAL_H
#define MROS_PC_TARGET_SYSSVC_SERIAL_H
#include "t_syslog.h"
#endif
