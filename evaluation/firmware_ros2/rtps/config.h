// SPDX-License-Identifier: BSD-3-Clause
// The board's embeddedRTPS settings the fit check reads (namespace
// rtps::Config of rtps/config.h): names in 40 bytes and 16 writers and
// readers a participant, as mros2-posix d267988 sets them; the rest chosen.
#ifndef EVALUATION_RTPS_CONFIG_H
#define EVALUATION_RTPS_CONFIG_H

#include <stdint.h>

namespace rtps {
namespace Config {
const uint8_t MAX_NUM_PARTICIPANTS = 1;
const uint8_t NUM_STATELESS_WRITERS = 16;
const uint8_t NUM_STATELESS_READERS = 16;
const uint8_t NUM_WRITERS_PER_PARTICIPANT = 16;
const uint8_t NUM_READERS_PER_PARTICIPANT = 16;
const uint8_t MAX_TYPENAME_LENGTH = 40;
const uint8_t MAX_TOPICNAME_LENGTH = 40;
const int THREAD_POOL_READER_STACKSIZE = 4096;
}  // namespace Config
}  // namespace rtps

#endif  // EVALUATION_RTPS_CONFIG_H
