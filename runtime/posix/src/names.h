// names.h: ROS graph names as roscpp resolves them: relative names live in
// the node's namespace, "~name" under the node, and command line remappings
// (from:=to) apply to the resolved names. Also the node's settings taken
// from the environment (ROS_MASTER_URI, ROS_IP / ROS_HOSTNAME,
// ROS_NAMESPACE) and the special arguments that override them (__master:=,
// __ip:=, __hostname:=, __name:=, __ns:=).
#ifndef MROS_POSIX_NAMES_H
#define MROS_POSIX_NAMES_H

#include <map>
#include <string>

namespace mros {
namespace posix {

struct NodeSettings {
  std::string name;        // resolved, e.g. "/mros_node"
  std::string namespace_;  // ends with '/'
  std::string master_uri;
  std::string host;        // what peers use to reach this node
  std::string bind_address;  // "" for every local address
  std::map<std::string, std::string> remappings;  // resolved from -> to

  static NodeSettings fromEnvironment(int argc, char** argv, const std::string& node_name);
  std::string resolve(const std::string& name) const;
};

}  // namespace posix
}  // namespace mros

#endif  // MROS_POSIX_NAMES_H
