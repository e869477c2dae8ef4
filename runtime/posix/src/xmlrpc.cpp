// xmlrpc.cpp: XML-RPC encoding and a small, depth-bounded XML reader for
// calls and answers (see xmlrpc.h; the HTTP side is in xmlrpc_http.cpp).
#include "xmlrpc.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace mros {
namespace posix {
namespace xmlrpc {

namespace {

const int kMaxValueDepth = 32;

// ---- encoding ----

void appendEscaped(std::string& out, const std::string& text) {
  for (char c : text) {
    switch (c) {
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '&': out += "&amp;"; break;
      default: out += c;
    }
  }
}

void appendValue(std::string& out, const Value& value) {
  out += "<value>";
  switch (value.kind) {
    case Value::kNil:
      out += "<nil/>";
      break;
    case Value::kInt:
      out += "<i4>" + std::to_string(value.integer) + "</i4>";
      break;
    case Value::kBool:
      out += value.integer ? "<boolean>1</boolean>" : "<boolean>0</boolean>";
      break;
    case Value::kDouble: {
      char text[64];
      std::snprintf(text, sizeof(text), "%.17g", value.real);
      out += std::string("<double>") + text + "</double>";
      break;
    }
    case Value::kString:
      out += "<string>";
      appendEscaped(out, value.text);
      out += "</string>";
      break;
    case Value::kArray:
      out += "<array><data>";
      for (const Value& item : value.items) {
        appendValue(out, item);
      }
      out += "</data></array>";
      break;
    case Value::kStruct:
      out += "<struct>";
      for (const auto& member : value.members) {
        out += "<member><name>";
        appendEscaped(out, member.first);
        out += "</name>";
        appendValue(out, member.second);
        out += "</member>";
      }
      out += "</struct>";
      break;
  }
  out += "</value>";
}

// ---- decoding: a forward-only reader over the XML text ----

class Reader {
 public:
  explicit Reader(const std::string& xml) : xml_(xml), pos_(0) {}

  // Consumes <name> (attributes ignored); self_closing tells <name/>.
  bool open(const char* name, bool* self_closing = nullptr) {
    std::string found;
    bool closes = false;
    const size_t saved = pos_;
    if (!readTag(found, closes) || found != name) {
      pos_ = saved;
      return false;
    }
    if (self_closing != nullptr) {
      *self_closing = closes;
    } else if (closes) {
      pos_ = saved;
      return false;
    }
    return true;
  }

  bool close(const char* name) {
    skipMarkup();
    const std::string tag = std::string("</") + name;
    if (xml_.compare(pos_, tag.size(), tag) != 0) {
      return false;
    }
    const size_t end = xml_.find('>', pos_);
    if (end == std::string::npos) {
      return false;
    }
    pos_ = end + 1;
    return true;
  }

  // Name of the next opening tag without consuming it ("" if none).
  std::string peekOpen() {
    const size_t saved = pos_;
    std::string name;
    bool closes = false;
    if (!readTag(name, closes)) {
      name.clear();
    }
    pos_ = saved;
    return name;
  }

  // Character data up to the next tag, entities decoded.
  bool text(std::string& out) {
    out.clear();
    while (pos_ < xml_.size() && xml_[pos_] != '<') {
      if (xml_[pos_] == '&') {
        if (!entity(out)) {
          return false;
        }
      } else {
        out += xml_[pos_++];
      }
    }
    return pos_ < xml_.size();
  }

  void skipMarkup() {
    for (;;) {
      skipSpace();
      if (xml_.compare(pos_, 2, "<?") == 0) {
        skipPast("?>");
      } else if (xml_.compare(pos_, 4, "<!--") == 0) {
        skipPast("-->");
      } else {
        return;
      }
    }
  }

 private:
  void skipSpace() {
    while (pos_ < xml_.size() && std::strchr(" \t\r\n", xml_[pos_]) != nullptr) {
      ++pos_;
    }
  }

  void skipPast(const char* marker) {
    const size_t end = xml_.find(marker, pos_);
    pos_ = end == std::string::npos ? xml_.size() : end + std::strlen(marker);
  }

  bool readTag(std::string& name, bool& self_closing) {
    skipMarkup();
    if (pos_ >= xml_.size() || xml_[pos_] != '<' || xml_.compare(pos_, 2, "</") == 0) {
      return false;
    }
    const size_t end = xml_.find('>', pos_);
    if (end == std::string::npos) {
      return false;
    }
    self_closing = xml_[end - 1] == '/';
    const size_t name_end = xml_.find_first_of(" \t\r\n/>", pos_ + 1);
    name = xml_.substr(pos_ + 1, name_end - pos_ - 1);
    pos_ = end + 1;
    return true;
  }

  bool entity(std::string& out) {
    const size_t end = xml_.find(';', pos_);
    if (end == std::string::npos || end - pos_ > 10) {
      return false;
    }
    const std::string name = xml_.substr(pos_ + 1, end - pos_ - 1);
    pos_ = end + 1;
    if (name == "lt") out += '<';
    else if (name == "gt") out += '>';
    else if (name == "amp") out += '&';
    else if (name == "quot") out += '"';
    else if (name == "apos") out += '\'';
    else if (name.size() > 1 && name[0] == '#') {
      const bool hex = name[1] == 'x' || name[1] == 'X';
      const unsigned long code = std::strtoul(name.c_str() + (hex ? 2 : 1), nullptr, hex ? 16 : 10);
      appendUtf8(out, code);
    } else {
      return false;
    }
    return true;
  }

  static void appendUtf8(std::string& out, unsigned long code) {
    if (code < 0x80) {
      out += static_cast<char>(code);
    } else if (code < 0x800) {
      out += static_cast<char>(0xC0 | (code >> 6));
      out += static_cast<char>(0x80 | (code & 0x3F));
    } else if (code < 0x10000) {
      out += static_cast<char>(0xE0 | (code >> 12));
      out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (code & 0x3F));
    } else {
      out += static_cast<char>(0xF0 | ((code >> 18) & 0x07));
      out += static_cast<char>(0x80 | ((code >> 12) & 0x3F));
      out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (code & 0x3F));
    }
  }

  const std::string& xml_;
  size_t pos_;
};

bool parseValue(Reader& in, Value& value, int depth);

bool parseScalar(Reader& in, const std::string& type, Value& value) {
  std::string text;
  if (!in.text(text)) {
    return false;
  }
  if (type == "string" || type == "base64" || type == "dateTime.iso8601") {
    value = Value::of(text);
  } else if (type == "int" || type == "i4" || type == "i8") {
    char* end = nullptr;
    errno = 0;
    value = Value::of(static_cast<int64_t>(std::strtoll(text.c_str(), &end, 10)));
    if (errno != 0 || end == text.c_str()) {
      return false;
    }
  } else if (type == "boolean") {
    value = Value::of(text == "1");
  } else if (type == "double") {
    value.kind = Value::kDouble;
    value.real = std::strtod(text.c_str(), nullptr);
  } else {
    return false;
  }
  return in.close(type.c_str());
}

bool parseValue(Reader& in, Value& value, int depth) {
  bool empty = false;
  if (depth > kMaxValueDepth || !in.open("value", &empty)) {
    return false;
  }
  if (empty) {
    value = Value::of("");
    return true;
  }
  const std::string type = in.peekOpen();
  if (type.empty()) {  // untyped content is a string
    std::string text;
    if (!in.text(text)) {
      return false;
    }
    value = Value::of(text);
    return in.close("value");
  }
  bool self_closing = false;
  in.open(type.c_str(), &self_closing);
  if (self_closing) {
    value = type == "nil" ? Value() : Value::of("");
  } else if (type == "array") {
    value = Value::list({});
    bool no_data = false;
    if (!in.open("data", &no_data)) {
      return false;
    }
    while (!no_data && in.peekOpen() == "value") {
      value.items.emplace_back();
      if (!parseValue(in, value.items.back(), depth + 1)) {
        return false;
      }
    }
    if ((!no_data && !in.close("data")) || !in.close("array")) {
      return false;
    }
  } else if (type == "struct") {
    value.kind = Value::kStruct;
    while (in.open("member")) {
      std::string name;
      if (!in.open("name") || !in.text(name) || !in.close("name")) {
        return false;
      }
      value.members.emplace_back(name, Value());
      if (!parseValue(in, value.members.back().second, depth + 1) || !in.close("member")) {
        return false;
      }
    }
    if (!in.close("struct")) {
      return false;
    }
  } else if (!parseScalar(in, type, value)) {
    return false;
  }
  return in.close("value");
}

bool parseParams(Reader& in, std::vector<Value>& params) {
  bool empty = false;
  if (!in.open("params", &empty)) {
    return false;
  }
  if (empty) {
    return true;
  }
  while (in.open("param")) {
    params.emplace_back();
    if (!parseValue(in, params.back(), 0) || !in.close("param")) {
      return false;
    }
  }
  return in.close("params");
}

}  // namespace

Value Value::of(int64_t v) {
  Value value;
  value.kind = kInt;
  value.integer = v;
  return value;
}

Value Value::of(const std::string& v) {
  Value value;
  value.kind = kString;
  value.text = v;
  return value;
}

Value Value::of(bool v) {
  Value value;
  value.kind = kBool;
  value.integer = v ? 1 : 0;
  return value;
}

Value Value::list(std::vector<Value> items) {
  Value value;
  value.kind = kArray;
  value.items = std::move(items);
  return value;
}

std::string encodeCall(const std::string& method, const std::vector<Value>& params) {
  std::string out = "<?xml version=\"1.0\"?>\n<methodCall><methodName>";
  appendEscaped(out, method);
  out += "</methodName><params>";
  for (const Value& param : params) {
    out += "<param>";
    appendValue(out, param);
    out += "</param>";
  }
  out += "</params></methodCall>\n";
  return out;
}

std::string encodeResponse(const Value& result) {
  std::string out = "<?xml version=\"1.0\"?>\n<methodResponse><params><param>";
  appendValue(out, result);
  out += "</param></params></methodResponse>\n";
  return out;
}

std::string encodeFault(int code, const std::string& message) {
  Value fault;
  fault.kind = Value::kStruct;
  fault.members.emplace_back("faultCode", Value::of(static_cast<int64_t>(code)));
  fault.members.emplace_back("faultString", Value::of(message));
  std::string out = "<?xml version=\"1.0\"?>\n<methodResponse><fault>";
  appendValue(out, fault);
  out += "</fault></methodResponse>\n";
  return out;
}

bool parseCall(const std::string& xml, std::string& method, std::vector<Value>& params) {
  Reader in(xml);
  params.clear();
  if (!in.open("methodCall") || !in.open("methodName") || !in.text(method) ||
      !in.close("methodName")) {
    return false;
  }
  if (in.peekOpen() == "params" && !parseParams(in, params)) {
    return false;
  }
  return in.close("methodCall");
}

bool parseResponse(const std::string& xml, Value& result, std::string& error) {
  Reader in(xml);
  if (!in.open("methodResponse")) {
    error = "not an XML-RPC response";
    return false;
  }
  if (in.open("fault")) {
    Value fault;
    error = "XML-RPC fault";
    if (parseValue(in, fault, 0)) {
      for (const auto& member : fault.members) {
        if (member.first == "faultString") {
          error += ": " + member.second.text;
        }
      }
    }
    return false;
  }
  std::vector<Value> params;
  if (!parseParams(in, params) || params.size() != 1 || !in.close("methodResponse")) {
    error = "malformed XML-RPC response";
    return false;
  }
  result = params[0];
  return true;
}

}  // namespace xmlrpc
}  // namespace posix
}  // namespace mros
