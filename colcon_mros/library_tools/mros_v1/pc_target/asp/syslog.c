/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * ASP's system log service (syssvc/syslog) on a PC: each syslog() call is
 * one line on stderr, "[level] text", formatted and written on the task
 * thread's host stack, as on the board ASP's logtask formats the line, not
 * the calling task. A call is a dispatch point, as a service call is.
 */
#include <stdarg.h>
#include <stdio.h>
#include <unistd.h>

#include "kernel.h"
#include "pc_target.h"
#include "t_syslog.h"

struct log_entry {
  unsigned int priority;
  const char *format;
  va_list arguments;
};

static void write_log_entry(void *entry_pointer) {
  static const char *const levels[] = {"emerg", "alert", "crit", "error",
                                       "warning", "notice", "info", "debug"};
  struct log_entry *entry = entry_pointer;
  char line[1024];
  int length;
  length = snprintf(line, sizeof line, "[%s] ", levels[entry->priority & 7u]);
  length += vsnprintf(line + length, sizeof line - (size_t)length - 1, entry->format,
                      entry->arguments);
  if (length > (int)sizeof line - 2) length = (int)sizeof line - 2;
  while (length > 0 && (line[length - 1] == '\n' || line[length - 1] == '\r')) length--;
  line[length++] = '\n';
  if (write(STDERR_FILENO, line, (size_t)length) < 0) {
    /* Nowhere left to report it. */
  }
}

/* Formatted and written on the host stack: on the board, ASP's logtask
 * formats the line, not the calling task. */
void syslog(unsigned int prio, const char *format, ...) {
  struct log_entry entry;
  entry.priority = prio;
  entry.format = format;
  va_start(entry.arguments, format);
  pc_on_host_stack(write_log_entry, &entry);
  va_end(entry.arguments);
  pc_dispatch_point();
}
