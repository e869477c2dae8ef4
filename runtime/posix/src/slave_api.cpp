// slave_api.cpp: the XML-RPC slave API of the node, as the ROS master and
// other nodes call it: requestTopic (answers with our TCPROS port),
// publisherUpdate (the master's new list of publishers of a topic we
// subscribe), getPid, getMasterUri, getPublications, getSubscriptions,
// getBusInfo, getBusStats, paramUpdate and shutdown.
#include <unistd.h>

#include "node.h"
#include "net.h"

namespace mros {
namespace posix {

namespace {

using xmlrpc::Value;

const int kSlaveCallTimeoutMs = 5000;

// ROS APIs answer [code, statusMessage, value].
Value rosResult(int code, const std::string& status, const Value& value) {
  return Value::list({Value::of(code), Value::of(status), value});
}

}  // namespace

void Node::serveSlaveCall(int fd) {
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
  // Answered first, so that the caller is not left waiting for a dead node.
  if (method == "shutdown" && !params.empty()) {
    const std::string reason = params.size() >= 2 ? params[1].text : "";
    shutdownAndExit("shutdown requested by " + params[0].text + " (" + reason + ")");
  }
}

Value Node::answer(const std::string& method, const std::vector<Value>& params) {
  const bool has_topic = params.size() >= 2 && params[1].isString();
  if (method == "requestTopic" && has_topic) {
    return requestTopic(params[1].text, params.size() >= 3 ? params[2] : Value());
  }
  if (method == "publisherUpdate" && has_topic && params.size() >= 3) {
    return publisherUpdate(params[1].text, params[2]);
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

Value Node::requestTopic(const std::string& topic, const Value& protocols) {
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

Value Node::publisherUpdate(const std::string& topic, const Value& publishers) {
  std::lock_guard<std::mutex> lock(mutex_);
  for (const auto& subscription : subscriptions_) {
    if (subscription->topic() == topic && ok()) {
      subscription->updatePublishers(uriList(publishers));
    }
  }
  return rosResult(1, "publisher update received", Value::of(0));
}

Value Node::topicList(bool publications) {
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

// [connectionId, destinationId, direction, transport, topic, connected, info]
Value Node::busInfo() {
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
                                      Value::of(std::string(1, c.direction)), Value::of("TCPROS"),
                                      Value::of(c.topic), Value::of(true), Value::of("")}));
  }
  return list;
}

}  // namespace posix
}  // namespace mros
