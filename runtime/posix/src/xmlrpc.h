// xmlrpc.h: the XML-RPC subset that the ROS master and slave APIs use
// (int, boolean, double, string, array, struct), over HTTP/1.x POST. Input
// from the network is size- and depth-bounded; anything else is an error.
#ifndef MROS_POSIX_XMLRPC_H
#define MROS_POSIX_XMLRPC_H

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace mros {
namespace posix {
namespace xmlrpc {

struct Value {
  enum Kind { kNil, kInt, kBool, kDouble, kString, kArray, kStruct };
  Kind kind = kNil;
  int64_t integer = 0;  // kInt, kBool
  double real = 0;      // kDouble
  std::string text;     // kString
  std::vector<Value> items;                           // kArray
  std::vector<std::pair<std::string, Value> > members;  // kStruct

  static Value of(int64_t v);
  static Value of(int v) { return of(static_cast<int64_t>(v)); }
  static Value of(const std::string& v);
  static Value of(const char* v) { return of(std::string(v)); }
  static Value of(bool v);
  static Value list(std::vector<Value> items);

  bool isInt() const { return kind == kInt; }
  bool isString() const { return kind == kString; }
  bool isArray() const { return kind == kArray; }
};

std::string encodeCall(const std::string& method, const std::vector<Value>& params);
std::string encodeResponse(const Value& result);
std::string encodeFault(int code, const std::string& message);

bool parseCall(const std::string& xml, std::string& method, std::vector<Value>& params);
// A fault response parses as false with the fault text in error.
bool parseResponse(const std::string& xml, Value& result, std::string& error);

// POSTs a call to an http://host:port/ URI and parses the answer.
bool call(const std::string& uri, const std::string& method, const std::vector<Value>& params,
          Value& result, std::string& error);

// ROS APIs answer [code, statusMessage, value]; true when code is 1.
bool callRosApi(const std::string& uri, const std::string& method,
                const std::vector<Value>& params, Value& value, std::string& error);

// Server side: reads one HTTP request body from fd; writes one response.
bool readRequest(int fd, std::string& body);
bool writeResponse(int fd, const std::string& body);

}  // namespace xmlrpc
}  // namespace posix
}  // namespace mros

#endif  // MROS_POSIX_XMLRPC_H
