// SPDX-License-Identifier: BSD-3-Clause
// The board's threads on the PC: every CMSIS-RTOS2 and sys_arch thread, and
// the tcpip thread, is a host thread started here.
#ifndef MROS2_PC_BOARD_THREADS_H
#define MROS2_PC_BOARD_THREADS_H

#include <stddef.h>
#include <stdint.h>

namespace mros2_pc {

typedef void (*ThreadBody)(void* argument);

// Starts body(argument) on a thread of its own. On the arm target the body
// runs on a stack of exactly stack_size bytes above a guard: a thread that
// would overrun its stack on the board stops the program with one line
// naming the setting that sizes it. Elsewhere it runs on its host stack.
// Returns an identifier for exit_thread's caller to compare with.
void* start_thread(const char* name, ThreadBody body, void* argument, size_t stack_size);

// The calling board thread's identifier (NULL on a thread not started here).
void* current_thread();

// Ends the calling board thread, as returning from its body does.
[[noreturn]] void exit_thread();

// Sleeps the calling thread, the board's RTOS tick being a millisecond.
void sleep_milliseconds(uint32_t milliseconds);

// Stops the program with one line, where the PC cannot stand in for the board
// (exit status 70, EX_SOFTWARE).
[[noreturn]] void stop(const char* what);

}  // namespace mros2_pc

#endif  // MROS2_PC_BOARD_THREADS_H
