// SPDX-License-Identifier: BSD-3-Clause
// The board config (rtps::Config) of the writer checks: what embeddedRTPS'
// StatefulWriter and StatelessWriter and the types they take read.
#ifndef RTPS_CONFIG_H
#define RTPS_CONFIG_H

#include <array>

#include "rtps/common/types.h"

namespace rtps {
namespace Config {
const uint8_t MAX_TYPENAME_LENGTH = 64;
const uint8_t MAX_TOPICNAME_LENGTH = 64;
const uint8_t NUM_READER_PROXIES_PER_WRITER = 4;
const uint8_t HISTORY_SIZE_STATELESS = 2;
const uint8_t HISTORY_SIZE_STATEFUL = 10;
const uint16_t SF_WRITER_HB_PERIOD_MS = 4000;
const int HEARTBEAT_STACKSIZE = 4096;
const int THREAD_POOL_NUM_WRITERS = 1;
const int THREAD_POOL_NUM_READERS = 1;
const int THREAD_POOL_WRITER_PRIO = 24;
const int THREAD_POOL_WORKLOAD_QUEUE_LENGTH = 20;
const uint8_t SPDP_MAX_NUM_LOCATORS = 5;
const Duration_t SPDP_DEFAULT_REMOTE_LEASE_DURATION = {100, 0};
const Duration_t SPDP_MAX_REMOTE_LEASE_DURATION = {180, 0};
const uint8_t DOMAIN_ID = 0;
const uint8_t MAX_NUM_UDP_CONNECTIONS = 4;
const VendorId_t VENDOR_ID = {{13, 37}};
const std::array<uint8_t, 4> IP_ADDRESS = {{192, 168, 11, 3}};
}  // namespace Config
}  // namespace rtps

#endif  // RTPS_CONFIG_H
