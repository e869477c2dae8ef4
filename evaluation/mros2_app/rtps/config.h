// SPDX-License-Identifier: BSD-3-Clause
// The embeddedRTPS settings (namespace rtps::Config) of the main job's mros2 app, a board
// config as an mros2 port writes one: the names embeddedRTPS and mros2 read, with values
// for an app of 7 publishers and 3 subscribers (16 writers and readers a participant, as
// mros2-posix sets them; type names in 64 bytes: genmros' patch node-in-the-ros-graph
// writes rmw_dds_common::msg::dds_::ParticipantEntitiesInfo_, 52 with its NUL). mros2 >= 0.5 defines IP_ADDRESS
// itself: this config declares it.
#ifndef RTPS_CONFIG_H
#define RTPS_CONFIG_H

// mros2's port layer: the FreeRTOS names embeddedRTPS uses, on CMSIS-RTOS2.
#include "mros2/freertos_conversion.h"
#include "rtps/common/types.h"

namespace rtps {

#define IS_LITTLE_ENDIAN 1
#define OS_IS_FREERTOS

namespace Config {
const VendorId_t VENDOR_ID = {13, 37};
extern std::array<uint8_t, 4> IP_ADDRESS;
const GuidPrefix_t BASE_GUID_PREFIX{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11};

const uint8_t DOMAIN_ID = 0;
const uint8_t NUM_STATELESS_WRITERS = 8;
const uint8_t NUM_STATELESS_READERS = 8;
const uint8_t NUM_STATEFUL_READERS = 4;
const uint8_t NUM_STATEFUL_WRITERS = 6;
const uint8_t MAX_NUM_PARTICIPANTS = 1;
const uint8_t NUM_WRITERS_PER_PARTICIPANT = 16;
const uint8_t NUM_READERS_PER_PARTICIPANT = 16;
const uint8_t NUM_WRITER_PROXIES_PER_READER = 6;
const uint8_t NUM_READER_PROXIES_PER_WRITER = 6;
const uint8_t MAX_NUM_UNMATCHED_REMOTE_WRITERS = 15;
const uint8_t MAX_NUM_UNMATCHED_REMOTE_READERS = 15;
const uint8_t MAX_NUM_READER_CALLBACKS = 5;
const uint8_t HISTORY_SIZE_STATELESS = 2;
const uint8_t HISTORY_SIZE_STATEFUL = 10;
const uint8_t MAX_TYPENAME_LENGTH = 64;
const uint8_t MAX_TOPICNAME_LENGTH = 40;

const int HEARTBEAT_STACKSIZE = 4096;           // bytes
const int THREAD_POOL_WRITER_STACKSIZE = 4096;  // bytes
const int THREAD_POOL_READER_STACKSIZE = 4096;  // bytes: the callbacks publish from here
const uint16_t SPDP_WRITER_STACKSIZE = 4096;    // bytes

const uint16_t SF_WRITER_HB_PERIOD_MS = 4000;
const uint16_t SPDP_RESEND_PERIOD_MS = 1000;
const uint8_t SPDP_CYCLECOUNT_HEARTBEAT = 2;
const uint8_t SPDP_WRITER_PRIO = 24;
const uint8_t SPDP_MAX_NUMBER_FOUND_PARTICIPANTS = 5;
const uint8_t SPDP_MAX_NUM_LOCATORS = 5;
const Duration_t SPDP_DEFAULT_REMOTE_LEASE_DURATION = {100, 0};
const Duration_t SPDP_MAX_REMOTE_LEASE_DURATION = {180, 0};
const Duration_t SPDP_LEASE_DURATION = {100, 0};

const int MAX_NUM_UDP_CONNECTIONS = 10;
const int THREAD_POOL_NUM_WRITERS = 1;
const int THREAD_POOL_NUM_READERS = 1;
const int THREAD_POOL_WRITER_PRIO = 24;
const int THREAD_POOL_READER_PRIO = 24;
const int THREAD_POOL_WORKLOAD_QUEUE_LENGTH = 20;
}  // namespace Config
}  // namespace rtps

#endif  // RTPS_CONFIG_H
