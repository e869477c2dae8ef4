/* SPDX-License-Identifier: BSD-3-Clause */
/* Stand-in for lwIP's init.h: mROS v1 includes it, uses nothing of it. */
