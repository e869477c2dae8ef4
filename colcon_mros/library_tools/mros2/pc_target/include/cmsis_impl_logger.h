// SPDX-License-Identifier: BSD-3-Clause
// The port's log lines (cmsis_impl_logger.h), which mros2's MROS2_DEBUG to
// MROS2_FATAL use: one line each on stdout, with its severity.
#ifndef MROS2_PC_CMSIS_IMPL_LOGGER_H
#define MROS2_PC_CMSIS_IMPL_LOGGER_H

#ifdef __cplusplus
extern "C" {
#endif
void mros2_pc_log(const char* severity, const char* format, ...)
    __attribute__((format(printf, 2, 3)));
#ifdef __cplusplus
}
#endif

#define CMSIS_IMPL_DEBUG(...) mros2_pc_log("DEBUG", __VA_ARGS__)
#define CMSIS_IMPL_INFO(...) mros2_pc_log("INFO", __VA_ARGS__)
#define CMSIS_IMPL_WARN(...) mros2_pc_log("WARN", __VA_ARGS__)
#define CMSIS_IMPL_ERROR(...) mros2_pc_log("ERROR", __VA_ARGS__)
#define CMSIS_IMPL_FATAL(...) mros2_pc_log("FATAL", __VA_ARGS__)

#endif  // MROS2_PC_CMSIS_IMPL_LOGGER_H
