// links.h: the node's topics and their TCPROS connections. A Publication
// owns the connections of ROS subscribers to this node (each with a sending
// queue and a sending thread: the paper's publishing task); a Subscription
// owns the connections this node opens to the publishers the master names
// (each with a receiving thread that decodes frames and runs the callback).
#ifndef MROS_POSIX_LINKS_H
#define MROS_POSIX_LINKS_H

#include <atomic>
#include <condition_variable>
#include <deque>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "mros_posix/core.h"
#include "tcpros.h"

namespace mros {
namespace posix {

// One line of the slave API's getBusInfo answer.
struct ConnectionInfo {
  int id;
  std::string peer;       // caller id of a subscriber, URI of a publisher
  char direction;         // 'o' we send, 'i' we receive
  std::string topic;
};

// What every connection of the node needs to know about the node.
struct NodeContext {
  std::string caller_id;
  std::mutex callback_mutex;  // callbacks never run concurrently
  std::atomic<int> next_connection_id{1};
};

class SubscriberLink;

class Publication {
 public:
  Publication(NodeContext& node, const std::string& topic, const TopicType& type,
              size_t queue_size);
  const std::string& topic() const { return topic_; }
  const TopicType& type() const { return type_; }

  void publish(const std::shared_ptr<const Frame>& frame);

  // Answers the connection header of a ROS subscriber that connected to this
  // node, then sends it this topic's messages until the connection drops.
  // Runs on the connection's own thread.
  void serve(int fd, const tcpros::Header& request);

  std::vector<ConnectionInfo> connections();
  void closeAll();

 private:
  NodeContext& node_;
  const std::string topic_;
  const TopicType type_;
  const size_t queue_size_;
  std::mutex mutex_;
  std::vector<std::shared_ptr<SubscriberLink> > links_;
};

class PublisherLink;

class Subscription {
 public:
  Subscription(NodeContext& node, const std::string& topic, const TopicType& type,
               Deliverer deliverer, void (*callback)(void*));
  const std::string& topic() const { return topic_; }
  const TopicType& type() const { return type_; }

  // The master's current list of publishers: new ones are connected, links
  // to the ones no longer listed are closed.
  void updatePublishers(const std::vector<std::string>& uris);

  std::vector<ConnectionInfo> connections();
  void closeAll();

 private:
  void run(std::shared_ptr<PublisherLink> link);
  // One connection attempt; true if it ended in a way worth retrying.
  bool connectAndReceive(PublisherLink& link);
  // Handshake and message loop on a connected socket; same return value.
  bool receive(PublisherLink& link, int fd);
  bool isListed(const std::string& uri);

  NodeContext& node_;
  const std::string topic_;
  const TopicType type_;
  const Deliverer deliverer_;
  void (*const callback_)(void*);
  std::mutex mutex_;
  std::vector<std::string> listed_;
  std::map<std::string, std::shared_ptr<PublisherLink> > links_;
};

}  // namespace posix
}  // namespace mros

#endif  // MROS_POSIX_LINKS_H
