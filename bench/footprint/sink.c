/* SPDX-License-Identifier: BSD-3-Clause */
/* Where the task's callback puts what it received, so nothing is optimized away. */
const void* volatile bench_received;
void bench_sink(const void* received) { bench_received = received; }
