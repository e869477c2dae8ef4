// SPDX-License-Identifier: BSD-3-Clause
// The board's threads on the PC (board_threads.h).
//
// On the arm target each thread's body runs on a stack of its board size,
// entered with makecontext/swapcontext from the host thread, above a guard
// region of no access. The host calls the stand-ins make (locks, sockets,
// printf) run on that stack too, as lwIP's, the RTOS's and the C library's
// calls do on the board; their frames are glibc's, not the board's. Each
// stack is painted, so that its peak use can be reported when the program
// is stopped. Elsewhere (native, with or without sanitizers) bodies run on
// their host thread's stack, and nothing is measured.
#ifndef _GNU_SOURCE
#define _GNU_SOURCE
#endif
#include "board_threads.h"

#include <pthread.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <time.h>
#include <ucontext.h>
#include <unistd.h>

#include "mros2_pc_settings.h"

namespace mros2_pc {
namespace {

// Large enough that a frame too big for the stack still lands in it.
const size_t kGuardBytes = 256 * 1024;
const size_t kSignalStackBytes = 64 * 1024;
// AAPCS: the stack pointer is 8-byte aligned at every call.
const size_t kStackAlignment = 8;
const unsigned char kPaint = 0xa5;
const int kMaxThreads = 64;
// A stopped program's exit status when a stack overflowed (EX_SOFTWARE).
const int kOverflowStatus = 70;

struct BoardThread {
  const char* name;
  size_t stack_size;
  ThreadBody body;
  void* argument;
  unsigned char* guard;  // kGuardBytes of no access right below low
  unsigned char* low;    // the board stack is [low, top)
  unsigned char* top;
  ucontext_t host;
  ucontext_t board;
  pthread_t host_thread;
};

BoardThread* threads[kMaxThreads];
int thread_count;
pthread_mutex_t threads_lock = PTHREAD_MUTEX_INITIALIZER;
__thread BoardThread* this_thread;

#if defined(__arm__)

struct ThreadSetting {
  const char* thread;
  const char* setting;
};
// Which setting sizes each named thread's stack (rendered by genmros from
// the board's files: mros2_pc_settings.h).
const ThreadSetting kThreadSettings[] = {MROS2_PC_THREAD_SETTINGS};

const char* setting_of(const char* name) {
  for (const ThreadSetting& entry : kThreadSettings) {
    if (strcmp(entry.thread, name) == 0) return entry.setting;
  }
  return "the size its creator passes";
}

size_t aligned(size_t bytes) { return (bytes + kStackAlignment - 1) & ~(kStackAlignment - 1); }

void give_signal_stack() {
  stack_t signal_stack;
  signal_stack.ss_sp = malloc(kSignalStackBytes);
  signal_stack.ss_size = kSignalStackBytes;
  signal_stack.ss_flags = 0;
  if (signal_stack.ss_sp == NULL || sigaltstack(&signal_stack, NULL) != 0) {
    stop("cannot set up a signal stack");
  }
}

bool in_guard(const BoardThread* thread, uintptr_t address) {
  return address >= (uintptr_t)thread->guard && address < (uintptr_t)thread->low;
}

// A guard hit stops the program with one line; any other fault takes its
// default action when the faulting instruction runs again.
void on_fault(int signal_number, siginfo_t* info, void* context) {
  const BoardThread* thread = this_thread;
  uintptr_t address = (uintptr_t)info->si_addr;
  uintptr_t sp = ((const ucontext_t*)context)->uc_mcontext.arm_sp;
  if (thread != NULL && (in_guard(thread, address) || in_guard(thread, sp))) {
    char line[512];
    uintptr_t deepest = address < sp && in_guard(thread, address) ? address : sp;
    int length = snprintf(line, sizeof line,
                          "mros2 PC target: thread %s overflowed its stack of %u bytes (%s); it "
                          "needs at least %u bytes\n",
                          thread->name, (unsigned)thread->stack_size, setting_of(thread->name),
                          (unsigned)aligned((uintptr_t)thread->top - deepest));
    if (write(STDERR_FILENO, line, (size_t)length) < 0) {
      // Nowhere left to report it.
    }
    _exit(kOverflowStatus);
  }
  signal(signal_number, SIG_DFL);
}

void map_stack(BoardThread* thread) {
  size_t page = (size_t)sysconf(_SC_PAGESIZE);
  size_t size = aligned(thread->stack_size);
  size_t mapped = (size + page - 1) / page * page;
  unsigned char* region = (unsigned char*)mmap(NULL, kGuardBytes + mapped, PROT_NONE,
                                               MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
  if (region == MAP_FAILED ||
      mprotect(region + kGuardBytes, mapped, PROT_READ | PROT_WRITE) != 0) {
    stop("cannot map a thread stack");
  }
  thread->guard = region;
  // The stack starts at the guard's end, so that an overrun of one byte
  // lands in it; the rest of the last page above the top is never used.
  thread->low = region + kGuardBytes;
  thread->top = thread->low + size;
  memset(thread->low, kPaint, size);
}

void run_body(void) {
  this_thread->body(this_thread->argument);
}

void* host_thread_main(void* argument) {
  BoardThread* thread = static_cast<BoardThread*>(argument);
  this_thread = thread;
  give_signal_stack();
  getcontext(&thread->board);
  thread->board.uc_stack.ss_sp = thread->low;
  thread->board.uc_stack.ss_size = (size_t)(thread->top - thread->low);
  thread->board.uc_link = &thread->host;
  makecontext(&thread->board, run_body, 0);
  swapcontext(&thread->host, &thread->board);
  return NULL;
}

// From the lowest byte that is no longer paint to the top.
size_t peak_use(const BoardThread* thread) {
  const volatile unsigned char* byte = thread->low;
  while (byte < thread->top && *byte == kPaint) byte++;
  return (size_t)(thread->top - (const unsigned char*)byte);
}

void report_stacks() {
  char line[256];
  int length = snprintf(line, sizeof line,
                        "mros2 PC target: thread stacks, peak use of the board's size:\n");
  if (write(STDERR_FILENO, line, (size_t)length) < 0) return;
  for (int index = 0; index < thread_count; index++) {
    const BoardThread* thread = threads[index];
    size_t size = (size_t)(thread->top - thread->low);
    size_t peak = peak_use(thread);
    length = snprintf(line, sizeof line, "  %-16s %6u of %6u bytes  %3u%%  (%s)\n", thread->name,
                      (unsigned)peak, (unsigned)size, (unsigned)(peak * 100u / size),
                      setting_of(thread->name));
    if (write(STDERR_FILENO, line, (size_t)length) < 0) return;
  }
}

void install_fault_handler() {
  struct sigaction action;
  memset(&action, 0, sizeof action);
  action.sa_sigaction = on_fault;
  action.sa_flags = SA_SIGINFO | SA_ONSTACK;
  sigemptyset(&action.sa_mask);
  sigaction(SIGSEGV, &action, NULL);
}

#else  // host stacks

void map_stack(BoardThread*) {}

void* host_thread_main(void* argument) {
  BoardThread* thread = static_cast<BoardThread*>(argument);
  this_thread = thread;
  thread->body(thread->argument);
  return NULL;
}

void report_stacks() {}

void install_fault_handler() {}

#endif

}  // namespace
}  // namespace mros2_pc

// gcov's, where the program is built with --coverage: a stop writes the counts, which
// _exit would otherwise lose.
extern "C" void __gcov_dump(void) __attribute__((weak));

namespace mros2_pc {
namespace {

void on_stop(int) {
  report_stacks();
  if (__gcov_dump != NULL) __gcov_dump();
  _exit(0);
}

}  // namespace

void* start_thread(const char* name, ThreadBody body, void* argument, size_t stack_size) {
  BoardThread* thread = new BoardThread();
  thread->name = name != NULL ? name : "(unnamed)";
  thread->stack_size = stack_size;
  thread->body = body;
  thread->argument = argument;
  map_stack(thread);
  pthread_mutex_lock(&threads_lock);
  if (thread_count == kMaxThreads) stop("more threads than the PC target keeps");
  threads[thread_count++] = thread;
  pthread_mutex_unlock(&threads_lock);
  pthread_attr_t attributes;
  pthread_attr_init(&attributes);
  pthread_attr_setdetachstate(&attributes, PTHREAD_CREATE_DETACHED);
  if (pthread_create(&thread->host_thread, &attributes, host_thread_main, thread) != 0) {
    stop("cannot start a thread");
  }
  pthread_attr_destroy(&attributes);
  return thread;
}

void* current_thread() { return this_thread; }

void sleep_milliseconds(uint32_t milliseconds) {
  struct timespec delay;
  delay.tv_sec = milliseconds / 1000;
  delay.tv_nsec = (long)(milliseconds % 1000) * 1000000;
  while (nanosleep(&delay, &delay) != 0) {
  }
}

void stop(const char* what) {
  fprintf(stderr, "mros2 PC target: %s\n", what);
  exit(kOverflowStatus);
}

void exit_thread() {
#if defined(__arm__)
  // Back to the host thread's context, which returns from the thread.
  setcontext(&this_thread->host);
#endif
  pthread_exit(NULL);
}

// Before main: the board's console writes each line as it ends, and a stop
// reports the stacks.
__attribute__((constructor)) static void prepare_board() {
  setvbuf(stdout, NULL, _IOLBF, 0);
  install_fault_handler();
  signal(SIGINT, on_stop);
  signal(SIGTERM, on_stop);
}

}  // namespace mros2_pc
