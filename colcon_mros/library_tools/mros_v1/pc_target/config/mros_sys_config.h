/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The app's own mros_sys_config.h, unchanged, with the addresses and ports
 * of the board's network replaced by the PC's ROS environment, read when
 * the node starts: the master from ROS_MASTER_URI, the node's address from
 * ROS_IP or ROS_HOSTNAME, and the slave (XML-RPC) and publisher (TCPROS)
 * ports from MROS_V1_SLAVE_PORT and MROS_V1_PUBLISHER_PORT (default: the
 * app's). The PC target's build puts this directory before the app's.
 */
#ifndef MROS_PC_TARGET_SYS_CONFIG_H
#define MROS_PC_TARGET_SYS_CONFIG_H

#include_next "mros_sys_config.h"

#ifdef __cplusplus
extern "C" {
#endif

const char *pc_master_host(void);
int pc_master_port(void);
const char *pc_node_host(void);
int pc_port_from_environment(const char *variable, int app_default);

#ifdef __cplusplus
}
#endif

/* The app's ports, kept before their macros are replaced. */
enum {
  pc_app_slave_port_no = MROS_SLAVE_PORT_NO,
  pc_app_publisher_port_no = MROS_PUBLISHER_PORT_NO
};
#undef MROS_MASTER_IPADDR
#undef MROS_MASTER_PORT_NO
#undef MROS_NODE_IPADDR
#undef MROS_SLAVE_PORT_NO
#undef MROS_PUBLISHER_PORT_NO
#define MROS_MASTER_IPADDR (pc_master_host())
#define MROS_MASTER_PORT_NO (pc_master_port())
#define MROS_NODE_IPADDR (pc_node_host())
#define MROS_SLAVE_PORT_NO (pc_port_from_environment("MROS_V1_SLAVE_PORT", pc_app_slave_port_no))
#define MROS_PUBLISHER_PORT_NO \
  (pc_port_from_environment("MROS_V1_PUBLISHER_PORT", pc_app_publisher_port_no))

#endif /* MROS_PC_TARGET_SYS_CONFIG_H */
