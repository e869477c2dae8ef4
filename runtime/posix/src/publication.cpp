// publication.cpp: the sending side of a topic. Each ROS subscriber that
// connects gets a SubscriberLink: a bounded queue of frames and a thread
// that writes them (the paper's publishing task), so a slow subscriber
// neither blocks publish() nor the other subscribers.
#include <cerrno>
#include <sys/socket.h>
#include <unistd.h>

#include "links.h"
#include "mros_log.h"
#include "net.h"

namespace mros {
namespace posix {

class SubscriberLink {
 public:
  SubscriberLink(int fd, int id, const std::string& caller_id, size_t queue_size)
      : id_(id),
        caller_id_(caller_id),
        queue_size_(queue_size),
        fd_(fd),
        closing_(false),
        sending_(false),
        head_offset_(0) {}

  int id() const { return id_; }
  const std::string& callerId() const { return caller_id_; }

  // An idle link is written to at once by the publishing thread, as far as
  // the socket takes it without blocking (roscpp does the same): this saves
  // the hand-over to the sending thread, which writes the rest. A full queue
  // drops its oldest frame not yet begun, as roscpp does (queue_size 0: no
  // limit).
  void enqueue(const std::shared_ptr<const Frame>& frame) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (closing_) {
      return;
    }
    if (!sending_ && queue_.empty()) {
      const ssize_t sent =
          send(fd_, frame->wire(), frame->wireSize(), MSG_DONTWAIT | MSG_NOSIGNAL);
      if (sent == static_cast<ssize_t>(frame->wireSize())) {
        return;
      }
      if (sent < 0 && errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR) {
        closing_ = true;
        wakeup_.notify_one();
        return;
      }
      head_offset_ = sent > 0 ? static_cast<size_t>(sent) : 0;
    } else if (queue_size_ != 0 && queue_.size() >= queue_size_) {
      const bool head_begun = head_offset_ > 0;
      if (!head_begun) {
        queue_.pop_front();
      } else if (queue_.size() > 1) {
        queue_.erase(queue_.begin() + 1);
      }
    }
    queue_.push_back(frame);
    wakeup_.notify_one();
  }

  // Writes queued frames until the connection fails or close() is called;
  // then closes the socket.
  void sendUntilClosed() {
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;) {
      wakeup_.wait(lock, [this] { return closing_ || !queue_.empty(); });
      if (closing_) {
        break;
      }
      const std::shared_ptr<const Frame> frame = queue_.front();
      const size_t offset = head_offset_;
      queue_.pop_front();
      head_offset_ = 0;
      sending_ = true;
      lock.unlock();
      const bool sent = net::sendAll(fd_, frame->wire() + offset, frame->wireSize() - offset);
      lock.lock();
      sending_ = false;
      if (!sent) {
        break;
      }
    }
    closing_ = true;
    queue_.clear();
    ::close(fd_);
    fd_ = -1;
  }

  void close() {
    std::lock_guard<std::mutex> lock(mutex_);
    closing_ = true;
    if (fd_ >= 0) {
      shutdown(fd_, SHUT_RDWR);
    }
    wakeup_.notify_one();
  }

 private:
  const int id_;
  const std::string caller_id_;
  const size_t queue_size_;
  std::mutex mutex_;
  std::condition_variable wakeup_;
  std::deque<std::shared_ptr<const Frame> > queue_;
  int fd_;
  bool closing_;
  bool sending_;        // the sending thread is writing a frame it took
  size_t head_offset_;  // bytes of queue_.front() already written
};

Publication::Publication(NodeContext& node, const std::string& topic, const TopicType& type,
                         size_t queue_size)
    : node_(node), topic_(topic), type_(type), queue_size_(queue_size) {}

void Publication::publish(const std::shared_ptr<const Frame>& frame) {
  std::lock_guard<std::mutex> lock(mutex_);
  for (const auto& link : links_) {
    link->enqueue(frame);
  }
}

void Publication::serve(int fd, const tcpros::Header& request) {
  const std::string caller = tcpros::field(request, "callerid");
  const std::string md5sum = tcpros::field(request, "md5sum");
  const std::string datatype = tcpros::field(request, "type");
  const bool md5_matches = md5sum == "*" || md5sum == type_.md5sum;
  const bool type_matches = datatype.empty() || datatype == "*" || datatype == type_.datatype;
  if (!md5_matches || !type_matches) {
    const std::string reason = "Client [" + caller + "] wants topic " + topic_ +
                               " to have datatype/md5sum [" + datatype + "/" + md5sum +
                               "], but our version has [" + type_.datatype + "/" +
                               type_.md5sum + "]. Dropping connection.";
    ROS_ERROR("%s", reason.c_str());
    tcpros::writeHeader(fd, {{"error", reason}});
    ::close(fd);
    return;
  }
  const tcpros::Header reply = {{"callerid", node_.caller_id},
                                {"topic", topic_},
                                {"type", type_.datatype},
                                {"md5sum", type_.md5sum},
                                {"message_definition", type_.definition},
                                {"latching", "0"}};
  if (!tcpros::writeHeader(fd, reply)) {
    ::close(fd);
    return;
  }
  if (tcpros::field(request, "tcp_nodelay") == "1") {
    net::setNoDelay(fd);
  }
  net::setTimeouts(fd, 0);
  const auto link = std::make_shared<SubscriberLink>(fd, node_.next_connection_id++, caller,
                                                     queue_size_);
  {
    std::lock_guard<std::mutex> lock(mutex_);
    links_.push_back(link);
  }
  ROS_INFO("subscriber %s connected to %s", caller.c_str(), topic_.c_str());
  link->sendUntilClosed();
  {
    std::lock_guard<std::mutex> lock(mutex_);
    for (auto it = links_.begin(); it != links_.end(); ++it) {
      if (*it == link) {
        links_.erase(it);
        break;
      }
    }
  }
  ROS_INFO("subscriber %s of %s disconnected", caller.c_str(), topic_.c_str());
}

std::vector<ConnectionInfo> Publication::connections() {
  std::lock_guard<std::mutex> lock(mutex_);
  std::vector<ConnectionInfo> result;
  for (const auto& link : links_) {
    result.push_back({link->id(), link->callerId(), 'o', topic_});
  }
  return result;
}

void Publication::closeAll() {
  std::lock_guard<std::mutex> lock(mutex_);
  for (const auto& link : links_) {
    link->close();
  }
}

}  // namespace posix
}  // namespace mros
