// SPDX-License-Identifier: BSD-3-Clause
// The board config (rtps::Config) of the receiver check: only what the
// receiver reads, the DATA_FRAG buffers of the patch
// data-frag-for-best-effort-readers, when the check is built with
// RECEIVER_CHECK_BUFFER_SIZE and RECEIVER_CHECK_BUFFERS; without them the
// patch's defaults hold.
#ifndef RTPS_CONFIG_H
#define RTPS_CONFIG_H

#include "rtps/common/types.h"

namespace rtps {
namespace Config {
#ifdef RECEIVER_CHECK_BUFFER_SIZE
const DataSize_t FRAGMENT_BUFFER_SIZE = RECEIVER_CHECK_BUFFER_SIZE;
const uint8_t FRAGMENT_BUFFERS = RECEIVER_CHECK_BUFFERS;
#endif
}  // namespace Config
}  // namespace rtps

#endif  // RTPS_CONFIG_H
