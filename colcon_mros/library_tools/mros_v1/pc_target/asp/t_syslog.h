/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * TOPPERS/ASP's system log on a PC: syslog() writes one line to stderr,
 * prefixed with its level, as ASP's log task writes to the serial port.
 */
#ifndef MROS_PC_TARGET_T_SYSLOG_H
#define MROS_PC_TARGET_T_SYSLOG_H

#ifdef __cplusplus
extern "C" {
#endif

#define LOG_EMERG 0U
#define LOG_ALERT 1U
#define LOG_CRIT 2U
#define LOG_ERROR 3U
#define LOG_WARNING 4U
#define LOG_NOTICE 5U
#define LOG_INFO 6U
#define LOG_DEBUG 7U

void syslog(unsigned int prio, const char *format, ...);

#ifdef __cplusplus
}
#endif

#endif /* MROS_PC_TARGET_T_SYSLOG_H */
