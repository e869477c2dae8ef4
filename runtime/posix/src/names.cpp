// names.cpp: name resolution and node settings (see names.h).
#include "names.h"

#include <arpa/inet.h>
#include <cstdlib>
#include <unistd.h>
#include <vector>

namespace mros {
namespace posix {

namespace {

std::string environment(const char* variable, const std::string& fallback) {
  const char* value = std::getenv(variable);
  return value != nullptr && *value != '\0' ? value : fallback;
}

std::string asNamespace(std::string name) {
  if (name.empty() || name[0] != '/') {
    name = "/" + name;
  }
  if (name.back() != '/') {
    name += '/';
  }
  return name;
}

std::string localHostName() {
  char name[256] = {0};
  return gethostname(name, sizeof(name) - 1) == 0 ? std::string(name) : "localhost";
}

bool isIpv4Literal(const std::string& host) {
  in_addr address;
  return inet_pton(AF_INET, host.c_str(), &address) == 1;
}

}  // namespace

NodeSettings NodeSettings::fromEnvironment(int argc, char** argv, const std::string& node_name) {
  std::map<std::string, std::string> special;
  std::vector<std::pair<std::string, std::string> > remaps;
  for (int i = 1; argv != nullptr && i < argc; ++i) {
    const std::string argument = argv[i];
    const size_t separator = argument.find(":=");
    if (separator == std::string::npos || separator == 0) {
      continue;
    }
    const std::string from = argument.substr(0, separator);
    const std::string to = argument.substr(separator + 2);
    if (from.compare(0, 2, "__") == 0) {
      special[from] = to;
    } else {
      remaps.emplace_back(from, to);
    }
  }
  NodeSettings settings;
  settings.master_uri = special.count("__master") != 0
                            ? special["__master"]
                            : environment("ROS_MASTER_URI", "http://localhost:11311/");
  settings.namespace_ = asNamespace(special.count("__ns") != 0 ? special["__ns"]
                                                               : environment("ROS_NAMESPACE", "/"));
  const std::string base_name = special.count("__name") != 0 ? special["__name"] : node_name;
  settings.name = base_name[0] == '/' ? base_name : settings.namespace_ + base_name;
  if (special.count("__ip") != 0) {
    settings.host = special["__ip"];
  } else if (special.count("__hostname") != 0) {
    settings.host = special["__hostname"];
  } else {
    settings.host = environment("ROS_IP", environment("ROS_HOSTNAME", localHostName()));
  }
  // A node advertised on a loopback or literal address need not listen on
  // the others.
  if (isIpv4Literal(settings.host)) {
    settings.bind_address = settings.host;
  } else if (settings.host == "localhost") {
    settings.bind_address = "127.0.0.1";
  }
  for (const auto& remap : remaps) {
    settings.remappings[settings.resolve(remap.first)] = settings.resolve(remap.second);
  }
  return settings;
}

std::string NodeSettings::resolve(const std::string& name) const {
  std::string resolved;
  if (name.empty()) {
    resolved = namespace_;
  } else if (name[0] == '/') {
    resolved = name;
  } else if (name[0] == '~') {
    resolved = this->name + "/" + name.substr(name.size() > 1 && name[1] == '/' ? 2 : 1);
  } else {
    resolved = namespace_ + name;
  }
  if (resolved.size() > 1 && resolved.back() == '/') {
    resolved.pop_back();
  }
  const auto remapped = remappings.find(resolved);
  return remapped == remappings.end() ? resolved : remapped->second;
}

}  // namespace posix
}  // namespace mros
