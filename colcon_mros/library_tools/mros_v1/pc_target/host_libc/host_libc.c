/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The host's C library in place of the board's newlib: the C library calls
 * the library and the app make run, on the arm target, on the calling task
 * thread's host stack (pc_target.h), as the host's C library is not the
 * board's newlib and its stack use tells nothing of the board's. The link wraps every function defined here as
 * __wrap_NAME (ld --wrap=NAME, listed from this object by mros_v1_pc.mk):
 * calls by name reach __wrap_NAME, which calls the host's __real_NAME.
 * String and memory functions stay where they are called: they are leaves
 * on the board as on the PC.
 */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>

#include "pc_target.h"

void *__real_malloc(size_t size);
void *__real_calloc(size_t count, size_t size);
void *__real_realloc(void *memory, size_t size);
void __real_free(void *memory);
long __real_strtol(const char *text, char **end, int base);
unsigned long __real_strtoul(const char *text, char **end, int base);
int __real_puts(const char *text);
int __real_vsnprintf(char *buffer, size_t size, const char *format, va_list arguments);
void __real_exit(int status) __attribute__((noreturn));

/* One call of any of them: what it is given and what it gives back. */
struct libc_call {
  void *memory;
  size_t count, size;
  const char *text;
  char **end;
  int base;
  long number;
  unsigned long unsigned_number;
  int status;
};

static void call_malloc(void *call) {
  struct libc_call *c = call;
  c->memory = __real_malloc(c->size);
}

static void call_calloc(void *call) {
  struct libc_call *c = call;
  c->memory = __real_calloc(c->count, c->size);
}

static void call_realloc(void *call) {
  struct libc_call *c = call;
  c->memory = __real_realloc(c->memory, c->size);
}

static void call_free(void *call) { __real_free(((struct libc_call *)call)->memory); }

static void call_strtol(void *call) {
  struct libc_call *c = call;
  c->number = __real_strtol(c->text, c->end, c->base);
}

static void call_strtoul(void *call) {
  struct libc_call *c = call;
  c->unsigned_number = __real_strtoul(c->text, c->end, c->base);
}

static void call_puts(void *call) {
  struct libc_call *c = call;
  c->status = __real_puts(c->text);
}

static void call_exit(void *call) { __real_exit(((struct libc_call *)call)->status); }

void *__wrap_malloc(size_t size) {
  struct libc_call call = {.size = size};
  pc_on_host_stack(call_malloc, &call);
  return call.memory;
}

void *__wrap_calloc(size_t count, size_t size) {
  struct libc_call call = {.count = count, .size = size};
  pc_on_host_stack(call_calloc, &call);
  return call.memory;
}

void *__wrap_realloc(void *memory, size_t size) {
  struct libc_call call = {.memory = memory, .size = size};
  pc_on_host_stack(call_realloc, &call);
  return call.memory;
}

void __wrap_free(void *memory) {
  struct libc_call call = {.memory = memory};
  pc_on_host_stack(call_free, &call);
}

long __wrap_strtol(const char *text, char **end, int base) {
  struct libc_call call = {.text = text, .end = end, .base = base};
  pc_on_host_stack(call_strtol, &call);
  return call.number;
}

unsigned long __wrap_strtoul(const char *text, char **end, int base) {
  struct libc_call call = {.text = text, .end = end, .base = base};
  pc_on_host_stack(call_strtoul, &call);
  return call.unsigned_number;
}

int __wrap_puts(const char *text) {
  struct libc_call call = {.text = text};
  pc_on_host_stack(call_puts, &call);
  return call.status;
}

void __wrap_exit(int status) {
  struct libc_call call = {.status = status};
  pc_on_host_stack(call_exit, &call);
  __builtin_unreachable();
}

/* ---- formatted input and output ---- */

struct formatted_call {
  FILE *stream;
  char *buffer;
  size_t size;
  const char *input;
  const char *format;
  va_list arguments;
  int result;
};

static void call_vsnprintf(void *call) {
  struct formatted_call *c = call;
  c->result = __real_vsnprintf(c->buffer, c->size, c->format, c->arguments);
}

static void call_vsprintf(void *call) {
  struct formatted_call *c = call;
  c->result = vsprintf(c->buffer, c->format, c->arguments);
}

static void call_vfprintf(void *call) {
  struct formatted_call *c = call;
  c->result = vfprintf(c->stream, c->format, c->arguments);
}

static void call_vsscanf(void *call) {
  struct formatted_call *c = call;
  c->result = vsscanf(c->input, c->format, c->arguments);
}

static int formatted(void (*function)(void *), struct formatted_call *call) {
  pc_on_host_stack(function, call);
  return call->result;
}

int __wrap_vsnprintf(char *buffer, size_t size, const char *format, va_list arguments) {
  struct formatted_call call = {.buffer = buffer, .size = size, .format = format};
  int result;
  va_copy(call.arguments, arguments);
  result = formatted(call_vsnprintf, &call);
  va_end(call.arguments);
  return result;
}

int __wrap_snprintf(char *buffer, size_t size, const char *format, ...) {
  struct formatted_call call = {.buffer = buffer, .size = size, .format = format};
  int result;
  va_start(call.arguments, format);
  result = formatted(call_vsnprintf, &call);
  va_end(call.arguments);
  return result;
}

int __wrap_sprintf(char *buffer, const char *format, ...) {
  struct formatted_call call = {.buffer = buffer, .format = format};
  int result;
  va_start(call.arguments, format);
  result = formatted(call_vsprintf, &call);
  va_end(call.arguments);
  return result;
}

int __wrap_fprintf(FILE *stream, const char *format, ...) {
  struct formatted_call call = {.stream = stream, .format = format};
  int result;
  va_start(call.arguments, format);
  result = formatted(call_vfprintf, &call);
  va_end(call.arguments);
  return result;
}

int __wrap_printf(const char *format, ...) {
  struct formatted_call call = {.stream = stdout, .format = format};
  int result;
  va_start(call.arguments, format);
  result = formatted(call_vfprintf, &call);
  va_end(call.arguments);
  return result;
}

/* sscanf as C99 headers name it. */
int __wrap___isoc99_sscanf(const char *input, const char *format, ...) {
  struct formatted_call call = {.input = input, .format = format};
  int result;
  va_start(call.arguments, format);
  result = formatted(call_vsscanf, &call);
  va_end(call.arguments);
  return result;
}
