// SPDX-License-Identifier: BSD-3-Clause
// The board config (rtps::Config) of the stateful reader check: what
// embeddedRTPS' StatefulReader and the types it takes read.
#ifndef RTPS_CONFIG_H
#define RTPS_CONFIG_H

#include <array>

#include "rtps/common/types.h"

namespace rtps {
namespace Config {
const uint8_t MAX_TYPENAME_LENGTH = 64;
const uint8_t MAX_TOPICNAME_LENGTH = 64;
const uint8_t NUM_WRITER_PROXIES_PER_READER = 4;
const uint16_t SF_WRITER_HB_PERIOD_MS = 4000;
const uint8_t DOMAIN_ID = 0;
const uint8_t MAX_NUM_UDP_CONNECTIONS = 4;
const VendorId_t VENDOR_ID = {{13, 37}};
const std::array<uint8_t, 4> IP_ADDRESS = {{192, 168, 11, 3}};
}  // namespace Config
}  // namespace rtps

#endif  // RTPS_CONFIG_H
