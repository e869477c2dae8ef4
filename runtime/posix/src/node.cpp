// node.cpp: the node's life (see node.h) and the core.h functions over it:
// start-up, registration of topics with the master over XML-RPC, accepting
// TCPROS subscribers, and a clean shutdown on SIGINT / SIGTERM.
#include "node.h"

#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <pthread.h>
#include <sys/socket.h>
#include <thread>
#include <unistd.h>

#include "mros_log.h"
#include "net.h"

namespace mros {
namespace posix {

namespace {

using xmlrpc::Value;

const int kHandshakeTimeoutMs = 5000;
const int kMasterRetryDelayMs = 500;
// Connections served at once on each port: slave API calls, and TCPROS
// subscribers (each holds its connection's thread while subscribed). More
// are refused at once, so no peer can make the node hold more threads.
const int kMaxSlaveCalls = 32;
const int kMaxSubscriberConnections = 64;
// A slave call or handshake needs little stack; a small one keeps the
// address space of many connections small.
const size_t kConnectionStackBytes = 256 * 1024;

}  // namespace

std::vector<std::string> uriList(const Value& value) {
  std::vector<std::string> uris;
  for (const Value& item : value.items) {
    if (item.isString()) {
      uris.push_back(item.text);
    }
  }
  return uris;
}

Node::Node(const NodeSettings& settings) : settings_(settings), shutting_down_(false) {
  context_.caller_id = settings.name;
}

bool Node::start() {
  uint16_t slave_port = 0;
  const int slave_fd = net::listenTcp(settings_.bind_address, slave_port);
  const int tcpros_fd = net::listenTcp(settings_.bind_address, tcpros_port_);
  if (slave_fd < 0 || tcpros_fd < 0) {
    ROS_FATAL("cannot listen on %s",
              settings_.bind_address.empty() ? "any address" : settings_.bind_address.c_str());
    return false;
  }
  slave_uri_ = "http://" + settings_.host + ":" + std::to_string(slave_port) + "/";
  std::thread(&Node::acceptLoop, this, slave_fd, &Node::serveSlaveCall, kMaxSlaveCalls).detach();
  std::thread(&Node::acceptLoop, this, tcpros_fd, &Node::serveTcpros, kMaxSubscriberConnections)
      .detach();
  std::thread(&Node::waitForSignals, this).detach();
  ROS_INFO("node %s started: slave API %s, TCPROS port %u, master %s", settings_.name.c_str(),
           slave_uri_.c_str(), tcpros_port_, settings_.master_uri.c_str());
  return true;
}

Publication* Node::advertise(const std::string& name, const TopicType& type, int queue_size) {
  const std::string topic = settings_.resolve(name);
  Publication* publication = nullptr;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    for (const auto& existing : publications_) {
      if (existing->topic() != topic) {
        continue;
      }
      if (existing->type().md5sum == type.md5sum) {
        return existing.get();  // one publication per topic, as in roscpp
      }
      ROS_ERROR("cannot advertise %s as [%s/%s]: it is already advertised as [%s/%s]",
                topic.c_str(), type.datatype.c_str(), type.md5sum.c_str(),
                existing->type().datatype.c_str(), existing->type().md5sum.c_str());
      return nullptr;
    }
    publication = new Publication(context_, topic, type,
                                  queue_size > 0 ? static_cast<size_t>(queue_size) : 0);
    publications_.emplace_back(publication);
  }
  Value subscribers;
  callMaster("registerPublisher", {Value::of(context_.caller_id), Value::of(topic),
                                   Value::of(type.datatype), Value::of(slave_uri_)},
             subscribers);
  ROS_INFO("advertised %s [%s]", topic.c_str(), type.datatype.c_str());
  return publication;
}

Subscription* Node::subscribe(const std::string& name, const TopicType& type,
                              Deliverer deliverer, void (*callback)(void*)) {
  const std::string topic = settings_.resolve(name);
  Subscription* subscription = new Subscription(context_, topic, type, deliverer, callback);
  {
    std::lock_guard<std::mutex> lock(mutex_);
    subscriptions_.emplace_back(subscription);
  }
  Value publishers;
  callMaster("registerSubscriber", {Value::of(context_.caller_id), Value::of(topic),
                                    Value::of(type.datatype), Value::of(slave_uri_)},
             publishers);
  ROS_INFO("subscribed to %s [%s]", topic.c_str(), type.datatype.c_str());
  subscription->updatePublishers(uriList(publishers));
  return subscription;
}

bool Node::beginShutdown(const std::string& reason) {
  bool expected = false;
  if (!shutting_down_.compare_exchange_strong(expected, true)) {
    return false;
  }
  ROS_INFO("shutting down node %s: %s", settings_.name.c_str(), reason.c_str());
  std::lock_guard<std::mutex> lock(mutex_);
  for (const auto& publication : publications_) {
    unregister("unregisterPublisher", publication->topic());
    publication->closeAll();
  }
  for (const auto& subscription : subscriptions_) {
    unregister("unregisterSubscriber", subscription->topic());
    subscription->closeAll();
  }
  return true;
}

void Node::shutdownAndExit(const std::string& reason) {
  if (beginShutdown(reason)) {
    std::fflush(nullptr);
    _exit(0);
  }
}

void Node::acceptLoop(int listen_fd, Server serve, int max_connections) {
  std::atomic<int> active(0);
  bool refusing = false;
  for (;;) {
    const int fd = accept4(listen_fd, nullptr, nullptr, SOCK_CLOEXEC);
    if (fd < 0) {  // out of descriptors, say: try again later
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
      continue;
    }
    const bool admitted = active.fetch_add(1) < max_connections &&
                          net::startThread([this, serve, fd, &active] {
                            (this->*serve)(fd);
                            active.fetch_sub(1);
                          }, kConnectionStackBytes);
    if (!admitted) {
      active.fetch_sub(1);
      close(fd);
      if (!refusing) {
        ROS_WARN("refusing connections: %d served at once, or no thread to serve one",
                 max_connections);
      }
    }
    refusing = !admitted;
  }
}

void Node::waitForSignals() {
  sigset_t signals;
  sigemptyset(&signals);
  sigaddset(&signals, SIGINT);
  sigaddset(&signals, SIGTERM);
  int received = 0;
  sigwait(&signals, &received);
  shutdownAndExit(received == SIGINT ? "SIGINT" : "SIGTERM");
}

// Blocks until the master answers, as roscpp does when it is not up yet.
void Node::callMaster(const std::string& method, const std::vector<Value>& params,
                      Value& value) {
  std::string error;
  bool reported = false;
  while (!xmlrpc::callRosApi(settings_.master_uri, method, params, value, error)) {
    if (!reported) {
      ROS_ERROR("%s to master at [%s] failed: %s. Retrying...", method.c_str(),
                settings_.master_uri.c_str(), error.c_str());
      reported = true;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(kMasterRetryDelayMs));
  }
}

void Node::unregister(const std::string& method, const std::string& topic) {
  Value ignored;
  std::string error;
  if (!xmlrpc::callRosApi(settings_.master_uri, method,
                          {Value::of(context_.caller_id), Value::of(topic), Value::of(slave_uri_)},
                          ignored, error)) {
    ROS_WARN("%s %s: %s", method.c_str(), topic.c_str(), error.c_str());
  }
}

void Node::serveTcpros(int fd) {
  net::setTimeouts(fd, kHandshakeTimeoutMs);
  tcpros::Header request;
  std::string error;
  if (!tcpros::readHeader(fd, request, error, net::Deadline::after(kHandshakeTimeoutMs))) {
    ROS_WARN("dropped a TCPROS connection: %s", error.c_str());
    close(fd);
    return;
  }
  const std::string topic = tcpros::field(request, "topic");
  Publication* publication = nullptr;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    for (const auto& candidate : publications_) {
      if (candidate->topic() == topic) {
        publication = candidate.get();
      }
    }
  }
  if (publication == nullptr || !ok()) {
    const std::string reason = "received a connection for topic [" + topic + "], which node " +
                               settings_.name + " does not publish";
    ROS_WARN("%s", reason.c_str());
    tcpros::writeHeader(fd, {{"error", reason}});
    close(fd);
    return;
  }
  publication->serve(fd, request);
}

// ---- core.h ----

namespace {

// The process's node. Never destroyed: its threads run until the process
// ends, and the exit paths unregister explicitly.
Node* the_node = nullptr;

Node& node() {
  if (the_node == nullptr) {
    ROS_FATAL("ros::init() must be called before using the node");
    std::abort();
  }
  return *the_node;
}

void unregisterAtExit() { the_node->beginShutdown("process exit"); }

}  // namespace

Frame::Frame(uint32_t body_size) : bytes_(new uint8_t[body_size + 4]), body_size_(body_size) {
  for (int i = 0; i < 4; ++i) {
    bytes_[i] = static_cast<uint8_t>(body_size >> (8 * i));
  }
}

void initNode(int argc, char** argv, const std::string& node_name) {
  if (the_node != nullptr) {
    ROS_ERROR("ros::init(%s): this process already runs a node", node_name.c_str());
    return;
  }
  // Signals are taken by the node's signal thread; every thread started
  // from now on inherits the mask.
  sigset_t signals;
  sigemptyset(&signals);
  sigaddset(&signals, SIGINT);
  sigaddset(&signals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &signals, nullptr);
  the_node = new Node(NodeSettings::fromEnvironment(argc, argv, node_name));
  if (!the_node->start()) {
    std::exit(1);
  }
  std::atexit(unregisterAtExit);
}

bool ok() { return the_node != nullptr && the_node->ok(); }

void spin() {
  for (;;) {
    pause();
  }
}

Publication* advertise(const std::string& topic, const TopicType& type, int queue_size) {
  return node().advertise(topic, type, queue_size);
}

void publish(Publication* publication, std::shared_ptr<const Frame> frame) {
  publication->publish(frame);
}

Subscription* subscribe(const std::string& topic, const TopicType& type, Deliverer deliverer,
                        void (*callback)(void*)) {
  return node().subscribe(topic, type, deliverer, callback);
}

}  // namespace posix
}  // namespace mros
