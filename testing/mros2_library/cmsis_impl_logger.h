// SPDX-License-Identifier: BSD-3-Clause
// mros2/logging.h includes cmsis-posix' logger; the check builds with
// MROS2_LOG_MIN_SEVERITY none, so nothing of it is used.
