// node.h: the node of the process: its topics, its registration with the
// ROS master, the slave API that the master and other nodes call, the
// TCPROS port that subscribers connect to, and its shutdown.
#ifndef MROS_POSIX_NODE_H
#define MROS_POSIX_NODE_H

#include <atomic>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "links.h"
#include "mros_posix/core.h"
#include "names.h"
#include "xmlrpc.h"

namespace mros {
namespace posix {

class Node {
 public:
  explicit Node(const NodeSettings& settings);

  // Opens the slave API and TCPROS ports and starts their threads.
  bool start();
  bool ok() const { return !shutting_down_; }

  Publication* advertise(const std::string& name, const TopicType& type, int queue_size);
  Subscription* subscribe(const std::string& name, const TopicType& type, Deliverer deliverer,
                          void (*callback)(void*));

  // Unregisters everything and closes every connection; false if shutdown
  // had begun already.
  bool beginShutdown(const std::string& reason);
  // beginShutdown, then ends the process with status 0 (the mROS v1 API has
  // no way back from spin() or from a user's endless loop).
  void shutdownAndExit(const std::string& reason);

 private:
  typedef void (Node::*Server)(int fd);

  // Serves each connection on a thread of its own, at most max_connections
  // at once; the others are closed at once.
  void acceptLoop(int listen_fd, Server serve, int max_connections);
  void waitForSignals();
  void callMaster(const std::string& method, const std::vector<xmlrpc::Value>& params,
                  xmlrpc::Value& value);
  void unregister(const std::string& method, const std::string& topic);

  // Slave API (slave_api.cpp).
  void serveSlaveCall(int fd);
  xmlrpc::Value answer(const std::string& method, const std::vector<xmlrpc::Value>& params);
  xmlrpc::Value requestTopic(const std::string& topic, const xmlrpc::Value& protocols);
  xmlrpc::Value publisherUpdate(const std::string& topic, const xmlrpc::Value& publishers);
  xmlrpc::Value topicList(bool publications);
  xmlrpc::Value busInfo();

  // A ROS subscriber connecting to one of our topics.
  void serveTcpros(int fd);

  const NodeSettings settings_;
  NodeContext context_;
  std::string slave_uri_;
  uint16_t tcpros_port_ = 0;
  std::atomic<bool> shutting_down_;
  std::mutex mutex_;  // guards the lists; topics are never removed
  std::vector<std::unique_ptr<Publication> > publications_;
  std::vector<std::unique_ptr<Subscription> > subscriptions_;
};

// The master's lists of URIs: the strings of an XML-RPC array.
std::vector<std::string> uriList(const xmlrpc::Value& value);

}  // namespace posix
}  // namespace mros

#endif  // MROS_POSIX_NODE_H
