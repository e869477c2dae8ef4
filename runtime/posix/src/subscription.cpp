// subscription.cpp: the receiving side of a topic. For every publisher the
// master lists, a PublisherLink thread asks that node for a TCPROS port
// (requestTopic), exchanges connection headers, then reads frames and has
// the type-specific deliverer decode them and run the callback. A dropped
// connection is retried while the master still lists the publisher; a
// refused handshake or a malformed frame closes the link for good.
#include <chrono>
#include <sys/socket.h>
#include <unistd.h>

#include "links.h"
#include "mros_log.h"
#include "net.h"
#include "xmlrpc.h"

namespace mros {
namespace posix {

namespace {
const int kHandshakeTimeoutMs = 5000;
const int kFirstRetryDelayMs = 100;
// A publisher that stays unreachable is tried less and less often.
const int kMaxRetryDelayMs = 10000;
// Publishers of one topic the node connects to (one thread each); anyone
// may call publisherUpdate, so a longer list must not make it hold more.
const size_t kMaxPublishersPerTopic = 32;
}  // namespace

class PublisherLink {
 public:
  PublisherLink(const std::string& uri, int id)
      : uri_(uri), id_(id), failed_attempts_(0), fd_(-1), stopped_(false) {}

  const std::string& uri() const { return uri_; }
  int id() const { return id_; }

  bool stopped() {
    std::lock_guard<std::mutex> lock(mutex_);
    return stopped_;
  }

  // The socket of the current attempt; false (and fd closed) if stopped.
  bool attach(int fd) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (stopped_) {
      ::close(fd);
      return false;
    }
    fd_ = fd;
    return true;
  }

  void detach() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (fd_ >= 0) {
      ::close(fd_);
      fd_ = -1;
    }
  }

  // Unblocks a read in progress and ends the link's thread.
  void stop() {
    std::lock_guard<std::mutex> lock(mutex_);
    stopped_ = true;
    if (fd_ >= 0) {
      shutdown(fd_, SHUT_RDWR);
    }
    wakeup_.notify_all();
  }

  // A dead publisher that the master still lists is retried for as long as
  // it is listed: only the first failure of a series is worth a warning.
  // (Used by the link's own thread only.)
  bool firstFailure() { return failed_attempts_++ == 0; }
  void connected() { failed_attempts_ = 0; }

  // Sleeps unless stopped meanwhile; returns false if stopped.
  bool pause(int milliseconds) {
    std::unique_lock<std::mutex> lock(mutex_);
    wakeup_.wait_for(lock, std::chrono::milliseconds(milliseconds), [this] { return stopped_; });
    return !stopped_;
  }

 private:
  const std::string uri_;
  const int id_;
  int failed_attempts_;
  std::mutex mutex_;
  std::condition_variable wakeup_;
  int fd_;
  bool stopped_;
};

Subscription::Subscription(NodeContext& node, const std::string& topic, const TopicType& type,
                           Deliverer deliverer, void (*callback)(void*))
    : node_(node), topic_(topic), type_(type), deliverer_(deliverer), callback_(callback) {}

void Subscription::updatePublishers(const std::vector<std::string>& all_uris) {
  std::vector<std::string> uris(all_uris);
  if (uris.size() > kMaxPublishersPerTopic) {
    ROS_WARN("%s: %zu publishers listed; connecting to the first %zu", topic_.c_str(), uris.size(),
             kMaxPublishersPerTopic);
    uris.resize(kMaxPublishersPerTopic);
  }
  std::lock_guard<std::mutex> lock(mutex_);
  listed_ = uris;
  for (auto& entry : links_) {
    bool still_listed = false;
    for (const std::string& uri : uris) {
      still_listed = still_listed || uri == entry.first;
    }
    if (!still_listed) {
      entry.second->stop();
    }
  }
  for (const std::string& uri : uris) {
    const auto existing = links_.find(uri);
    if (existing != links_.end() && !existing->second->stopped()) {
      continue;
    }
    const auto link = std::make_shared<PublisherLink>(uri, node_.next_connection_id++);
    if (!net::startThread([this, link] { run(link); })) {
      ROS_WARN("%s: no thread for publisher %s; it is tried again with the next update",
               topic_.c_str(), uri.c_str());
      continue;
    }
    links_[uri] = link;
  }
}

bool Subscription::isListed(const std::string& uri) {
  std::lock_guard<std::mutex> lock(mutex_);
  for (const std::string& listed : listed_) {
    if (listed == uri) {
      return true;
    }
  }
  return false;
}

void Subscription::run(std::shared_ptr<PublisherLink> link) {
  int delay_ms = kFirstRetryDelayMs;
  while (connectAndReceive(*link) && isListed(link->uri()) && link->pause(delay_ms)) {
    delay_ms = std::min(delay_ms * 2, kMaxRetryDelayMs);
  }
  std::lock_guard<std::mutex> lock(mutex_);
  const auto found = links_.find(link->uri());
  if (found != links_.end() && found->second == link) {
    links_.erase(found);
  }
}

bool Subscription::connectAndReceive(PublisherLink& link) {
  const char* topic = topic_.c_str();
  const char* uri = link.uri().c_str();
  xmlrpc::Value protocols = xmlrpc::Value::list({xmlrpc::Value::list({xmlrpc::Value::of("TCPROS")})});
  xmlrpc::Value answer;
  std::string error;
  if (!xmlrpc::callRosApi(link.uri(), "requestTopic",
                          {xmlrpc::Value::of(node_.caller_id), xmlrpc::Value::of(topic_), protocols},
                          answer, error)) {
    if (link.firstFailure()) {
      ROS_WARN("%s: publisher %s not reachable: %s; retrying while the master lists it", topic,
               uri, error.c_str());
    }
    return true;
  }
  if (!answer.isArray() || answer.items.size() < 3 || answer.items[0].text != "TCPROS" ||
      !answer.items[1].isString() || !answer.items[2].isInt() || answer.items[2].integer <= 0 ||
      answer.items[2].integer > 65535) {
    ROS_ERROR("%s: publisher %s answered requestTopic without a TCPROS address", topic, uri);
    return false;
  }
  const net::HostPort address = {answer.items[1].text,
                                 static_cast<uint16_t>(answer.items[2].integer)};
  const int fd = net::connectTcp(address, kHandshakeTimeoutMs, error);
  if (fd < 0) {
    if (link.firstFailure()) {
      ROS_WARN("%s: cannot connect to publisher %s: %s; retrying while the master lists it",
               topic, uri, error.c_str());
    }
    return true;
  }
  if (!link.attach(fd)) {
    return false;
  }
  const bool retry = receive(link, fd);
  link.detach();
  return retry;
}

bool Subscription::receive(PublisherLink& link, int fd) {
  const char* topic = topic_.c_str();
  const char* uri = link.uri().c_str();
  net::setTimeouts(fd, kHandshakeTimeoutMs);
  const tcpros::Header request = {{"callerid", node_.caller_id},
                                  {"topic", topic_},
                                  {"type", type_.datatype},
                                  {"md5sum", type_.md5sum},
                                  {"message_definition", type_.definition},
                                  {"tcp_nodelay", "1"}};
  tcpros::Header reply;
  std::string error;
  if (!tcpros::writeHeader(fd, request) ||
      !tcpros::readHeader(fd, reply, error, net::Deadline::after(kHandshakeTimeoutMs))) {
    ROS_ERROR("%s: bad connection header from publisher %s: %s", topic, uri, error.c_str());
    return false;
  }
  if (!tcpros::field(reply, "error").empty()) {
    ROS_ERROR("%s: publisher %s refused the connection: %s", topic, uri,
              tcpros::field(reply, "error").c_str());
    return false;
  }
  const std::string md5sum = tcpros::field(reply, "md5sum");
  const std::string datatype = tcpros::field(reply, "type");
  if ((md5sum != "*" && md5sum != type_.md5sum) ||
      (!datatype.empty() && datatype != "*" && datatype != type_.datatype)) {
    ROS_ERROR("%s: publisher %s sends [%s/%s], but we subscribed with [%s/%s]. Dropping connection.",
              topic, uri, datatype.c_str(), md5sum.c_str(), type_.datatype.c_str(),
              type_.md5sum.c_str());
    return false;
  }
  net::setTimeouts(fd, 0);
  net::setNoDelay(fd);
  ROS_INFO("%s: connected to publisher %s", topic, uri);
  link.connected();
  std::vector<uint8_t> body;
  for (;;) {
    const tcpros::FrameStatus status = tcpros::readFrame(fd, body, error);
    if (status == tcpros::kStreamEnded) {
      ROS_INFO("%s: publisher %s disconnected (%s)", topic, uri, error.c_str());
      return !link.stopped();
    }
    if (status == tcpros::kFrameTooLarge) {
      ROS_ERROR("%s: malformed frame from publisher %s: %s; closing the connection", topic, uri,
                error.c_str());
      return false;
    }
    std::lock_guard<std::mutex> lock(node_.callback_mutex);
    if (!deliverer_(callback_, body.data(), static_cast<uint32_t>(body.size()))) {
      ROS_ERROR("%s: malformed %s message of %zu bytes from publisher %s; closing the connection",
                topic, type_.datatype.c_str(), body.size(), uri);
      return false;
    }
  }
}

std::vector<ConnectionInfo> Subscription::connections() {
  std::lock_guard<std::mutex> lock(mutex_);
  std::vector<ConnectionInfo> result;
  for (const auto& entry : links_) {
    result.push_back({entry.second->id(), entry.first, 'i', topic_});
  }
  return result;
}

void Subscription::closeAll() {
  std::lock_guard<std::mutex> lock(mutex_);
  listed_.clear();
  for (const auto& entry : links_) {
    entry.second->stop();
  }
}

}  // namespace posix
}  // namespace mros
