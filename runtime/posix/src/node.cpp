// node.cpp: the node itself (the core.h functions). It registers topics with
// the ROS master over XML-RPC, serves the slave API that masters and other
// nodes call (requestTopic, publisherUpdate, getPid, getBusInfo, shutdown
// ...), accepts TCPROS subscribers, and shuts down cleanly on SIGINT /
// SIGTERM or a remote shutdown request.
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <pthread.h>
#include <sys/socket.h>
#include <thread>
#include <unistd.h>

#include "links.h"
#include "mros_log.h"
#include "mros_posix/core.h"
#include "names.h"
#include "net.h"
#include "xmlrpc.h"

namespace mros {
namespace posix {

namespace {

using xmlrpc::Value;

const int kSlaveCallTimeoutMs = 5000;
const int kMasterRetryDelayMs = 500;

Value rosResult(int code, const std::string& status, const Value& value) {
  return Value::list({Value::of(code), Value::of(status), value});
}

class Node {
 public:
  explicit Node(const NodeSettings& settings) : settings_(settings), shutting_down_(false) {
    context_.caller_id = settings.name;
  }

  bool start() {
    uint16_t slave_port = 0;
    slave_fd_ = net::listenTcp(settings_.bind_address, slave_port);
    tcpros_fd_ = net::listenTcp(settings_.bind_address, tcpros_port_);
    if (slave_fd_ < 0 || tcpros_fd_ < 0) {
      ROS_FATAL("cannot listen on %s", settings_.bind_address.empty() ? "any address"
                                                                      : settings_.bind_address.c_str());
      return false;
    }
    slave_uri_ = "http://" + settings_.host + ":" + std::to_string(slave_port) + "/";
    std::thread(&Node::acceptLoop, this, slave_fd_, &Node::serveSlaveCall).detach();
    std::thread(&Node::acceptLoop, this, tcpros_fd_, &Node::serveTcpros).detach();
    std::thread(&Node::waitForSignals, this).detach();
    ROS_INFO("node %s started: slave API %s, TCPROS port %u, master %s", settings_.name.c_str(),
             slave_uri_.c_str(), tcpros_port_, settings_.master_uri.c_str());
    return true;
  }

  bool ok() const { return !shutting_down_; }

  Publication* advertise(const std::string& name, const TopicType& type, int queue_size) {
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

  Subscription* subscribe(const std::string& name, const TopicType& type, Deliverer deliverer,
                          void (*callback)(void*)) {
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

  // Unregisters everything and closes every connection; once.
  bool beginShutdown(const std::string& reason) {
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

  void shutdownAndExit(const std::string& reason) {
    if (beginShutdown(reason)) {
      std::fflush(nullptr);
      _exit(0);
    }
  }

 private:
  typedef void (Node::*Server)(int fd);

  void acceptLoop(int listen_fd, Server serve) {
    for (;;) {
      const int fd = accept4(listen_fd, nullptr, nullptr, SOCK_CLOEXEC);
      if (fd < 0) {
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
        continue;
      }
      std::thread(serve, this, fd).detach();
    }
  }

  void waitForSignals() {
    sigset_t signals;
    sigemptyset(&signals);
    sigaddset(&signals, SIGINT);
    sigaddset(&signals, SIGTERM);
    int received = 0;
    sigwait(&signals, &received);
    shutdownAndExit(received == SIGINT ? "SIGINT" : "SIGTERM");
  }

  // Blocks until the master answers, as roscpp does when it is not up yet.
  void callMaster(const std::string& method, const std::vector<Value>& params, Value& value) {
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

  void unregister(const std::string& method, const std::string& topic) {
    Value ignored;
    std::string error;
    if (!xmlrpc::callRosApi(settings_.master_uri, method,
                            {Value::of(context_.caller_id), Value::of(topic), Value::of(slave_uri_)},
                            ignored, error)) {
      ROS_WARN("%s %s: %s", method.c_str(), topic.c_str(), error.c_str());
    }
  }

  static std::vector<std::string> uriList(const Value& value) {
    std::vector<std::string> uris;
    for (const Value& item : value.items) {
      if (item.isString()) {
        uris.push_back(item.text);
      }
    }
    return uris;
  }

  // ---- slave API ----

  void serveSlaveCall(int fd) {
    net::setTimeouts(fd, kSlaveCallTimeoutMs);
    std::string body;
    std::string method;
    std::vector<Value> params;
    if (xmlrpc::readRequest(fd, body)) {
      const bool parsed = xmlrpc::parseCall(body, method, params);
      xmlrpc::writeResponse(fd, parsed ? xmlrpc::encodeResponse(answer(method, params))
                                       : xmlrpc::encodeFault(-1, "malformed XML-RPC call"));
    }
    close(fd);
    if (method == "shutdown" && params.size() >= 1) {
      const std::string reason = params.size() >= 2 ? params[1].text : "";
      shutdownAndExit("shutdown requested by " + params[0].text + " (" + reason + ")");
    }
  }

  Value answer(const std::string& method, const std::vector<Value>& params) {
    const bool has_topic = params.size() >= 2 && params[1].isString();
    if (method == "requestTopic" && has_topic) {
      return requestTopic(params[1].text, params.size() >= 3 ? params[2] : Value());
    }
    if (method == "publisherUpdate" && has_topic && params.size() >= 3) {
      std::lock_guard<std::mutex> lock(mutex_);
      for (const auto& subscription : subscriptions_) {
        if (subscription->topic() == params[1].text && ok()) {
          subscription->updatePublishers(uriList(params[2]));
        }
      }
      return rosResult(1, "publisher update received", Value::of(0));
    }
    if (method == "getPid") {
      return rosResult(1, "", Value::of(static_cast<int64_t>(getpid())));
    }
    if (method == "getMasterUri") {
      return rosResult(1, "", Value::of(settings_.master_uri));
    }
    if (method == "getPublications" || method == "getSubscriptions") {
      return rosResult(1, "", topicList(method == "getPublications"));
    }
    if (method == "getBusInfo") {
      return rosResult(1, "bus info", busInfo());
    }
    if (method == "getBusStats") {
      return rosResult(1, "", Value::list({Value::list({}), Value::list({}), Value::list({})}));
    }
    if (method == "shutdown") {
      return rosResult(1, "shutdown", Value::of(0));
    }
    if (method == "paramUpdate") {
      return rosResult(1, "", Value::of(0));
    }
    return rosResult(-1, "unsupported call " + method, Value::of(0));
  }

  Value requestTopic(const std::string& topic, const Value& protocols) {
    bool offers_tcpros = false;
    for (const Value& protocol : protocols.items) {
      offers_tcpros = offers_tcpros || (!protocol.items.empty() && protocol.items[0].text == "TCPROS");
    }
    std::lock_guard<std::mutex> lock(mutex_);
    bool publishing = false;
    for (const auto& publication : publications_) {
      publishing = publishing || publication->topic() == topic;
    }
    if (!publishing) {
      return rosResult(0, "Not a publisher of [" + topic + "]", Value::list({}));
    }
    if (!offers_tcpros) {
      return rosResult(0, "no supported protocol implementations", Value::list({}));
    }
    return rosResult(1, "ready on " + settings_.host + ":" + std::to_string(tcpros_port_),
                     Value::list({Value::of("TCPROS"), Value::of(settings_.host),
                                  Value::of(static_cast<int64_t>(tcpros_port_))}));
  }

  Value topicList(bool publications) {
    std::lock_guard<std::mutex> lock(mutex_);
    Value list = Value::list({});
    if (publications) {
      for (const auto& p : publications_) {
        list.items.push_back(Value::list({Value::of(p->topic()), Value::of(p->type().datatype)}));
      }
    } else {
      for (const auto& s : subscriptions_) {
        list.items.push_back(Value::list({Value::of(s->topic()), Value::of(s->type().datatype)}));
      }
    }
    return list;
  }

  Value busInfo() {
    std::vector<ConnectionInfo> connections;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      for (const auto& p : publications_) {
        const auto more = p->connections();
        connections.insert(connections.end(), more.begin(), more.end());
      }
      for (const auto& s : subscriptions_) {
        const auto more = s->connections();
        connections.insert(connections.end(), more.begin(), more.end());
      }
    }
    Value list = Value::list({});
    for (const ConnectionInfo& c : connections) {
      list.items.push_back(Value::list({Value::of(c.id), Value::of(c.peer),
                                        Value::of(std::string(1, c.direction)),
                                        Value::of("TCPROS"), Value::of(c.topic), Value::of(true),
                                        Value::of("")}));
    }
    return list;
  }

  // ---- TCPROS server: a ROS subscriber connecting to one of our topics ----

  void serveTcpros(int fd) {
    net::setTimeouts(fd, kSlaveCallTimeoutMs);
    tcpros::Header request;
    std::string error;
    if (!tcpros::readHeader(fd, request, error)) {
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
      const std::string reason = "received a connection for topic [" + topic +
                                 "], which node " + settings_.name + " does not publish";
      ROS_WARN("%s", reason.c_str());
      tcpros::writeHeader(fd, {{"error", reason}});
      close(fd);
      return;
    }
    publication->serve(fd, request);
  }

  const NodeSettings settings_;
  NodeContext context_;
  std::string slave_uri_;
  uint16_t tcpros_port_ = 0;
  int slave_fd_ = -1;
  int tcpros_fd_ = -1;
  std::atomic<bool> shutting_down_;
  std::mutex mutex_;  // guards the lists; topics are never removed
  std::vector<std::unique_ptr<Publication> > publications_;
  std::vector<std::unique_ptr<Subscription> > subscriptions_;
};

// The process's node. Never destroyed: its threads run until the process
// ends, and exit paths unregister explicitly.
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
