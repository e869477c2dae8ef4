/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Where the node on the PC finds the master and itself: ROS_MASTER_URI,
 * ROS_IP/ROS_HOSTNAME and the port variables of mros_sys_config.h. A value
 * that cannot be used stops the node at start-up with one line.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "lwip/netif.h"

const char *pc_master_host(void);
int pc_master_port(void);
const char *pc_node_host(void);
int pc_port_from_environment(const char *variable, int app_default);

static char master_host[256];
static int master_port;

static void stop(const char *variable, const char *value, const char *expected) {
  fprintf(stderr, "mROS PC target: %s=%s: %s\n", variable, value != NULL ? value : "", expected);
  exit(2);
}

static int parse_port(const char *variable, const char *text) {
  char *end = NULL;
  long port = strtol(text, &end, 10);
  if (end == text || (*end != '\0' && *end != '/') || port < 1 || port > 65535) {
    stop(variable, text, "not a TCP port (1 to 65535)");
  }
  return (int)port;
}

static void read_master_uri(void) {
  const char *uri = getenv("ROS_MASTER_URI");
  const char *host;
  const char *colon;
  size_t length;
  if (master_port != 0) return;
  if (uri == NULL || uri[0] == '\0') stop("ROS_MASTER_URI", uri, "not set (http://HOST:PORT)");
  if (strncmp(uri, "http://", 7) != 0) stop("ROS_MASTER_URI", uri, "not http://HOST:PORT");
  host = uri + 7;
  colon = strchr(host, ':');
  if (colon == NULL) stop("ROS_MASTER_URI", uri, "not http://HOST:PORT");
  length = (size_t)(colon - host);
  if (length == 0 || length >= sizeof master_host) stop("ROS_MASTER_URI", uri, "no host name");
  memcpy(master_host, host, length);
  master_host[length] = '\0';
  master_port = parse_port("ROS_MASTER_URI", colon + 1);
}

const char *pc_master_host(void) {
  read_master_uri();
  return master_host;
}

int pc_master_port(void) {
  read_master_uri();
  return master_port;
}

const char *pc_node_host(void) { return pc_node_address(); }

int pc_port_from_environment(const char *variable, int app_default) {
  const char *value = getenv(variable);
  if (value == NULL || value[0] == '\0') return app_default;
  return parse_port(variable, value);
}
