/* SPDX-License-Identifier: BSD-3-Clause */
/* mbed 2's EthernetInterface on a PC: the interface is the PC's, already up,
 * with the address the node uses for ROS (ROS_IP, ROS_HOSTNAME, 127.0.0.1). */
#ifndef MROS_PC_TARGET_ETHERNETINTERFACE_H
#define MROS_PC_TARGET_ETHERNETINTERFACE_H

#include "mbed.h"

class EthernetInterface {
 public:
  static int init();
  static int init(const char *ip, const char *mask, const char *gateway);
  static int connect(unsigned int timeout_ms = 15000);
  static int disconnect();
  static char *getMACAddress();
  static char *getIPAddress();
  static char *getGateway();
  static char *getNetworkMask();
};

#endif /* MROS_PC_TARGET_ETHERNETINTERFACE_H */
