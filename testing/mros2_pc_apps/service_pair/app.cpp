/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * An mros2 app that serves and calls a service (genmros' mros2 patch services-both-ways),
 * rcl_interfaces/srv/GetParameterTypes, whose request holds names and reply types:
 * - it serves parameter_types: each name's type is its length;
 * - it calls the ROS side's name_lengths once the service is ready: call i asks for the
 *   names "call i" and i times "x" (none for call 0), and holds the reply to the same rule.
 * It prints "call i ok" or "call i failed: <why>" for each of CALLS calls, "calls done" after
 * them; every 10 requests, how many it answered and how many replies the reply writer refused
 * ("requests N (M replies refused)").
 */
#include "mros2.h"
#include "rcl_interfaces/srv/get_parameter_types.hpp"

#include "cmsis_os.h"
#include "netif.h"
#include "netif_posix_add.h"

#include <stdio.h>
#include <string>

namespace {

typedef rcl_interfaces::srv::GetParameterTypes GetParameterTypes;
const int CALLS = 100;
const uint32_t CALL_TIMEOUT_MS = 5000;
int requests_answered;

void name_lengths(GetParameterTypes::Request *request, GetParameterTypes::Response *response)
{
  for (const auto &name : request->names) {
    response->types.push_back(static_cast<uint8_t>(name.size()));
  }
  if (++requests_answered % 10 == 0) {
    printf("requests %d (%u replies refused)\n", requests_answered,
           (unsigned)mros2::Service::refused_replies);
    fflush(stdout);
  }
}

const char *check_reply(const GetParameterTypes::Request &request,
                        const GetParameterTypes::Response &response)
{
  if (response.types.size() != request.names.size()) {
    return "as many types as names";
  }
  for (size_t i = 0; i < request.names.size(); ++i) {
    if (response.types[i] != request.names[i].size()) {
      return "a type not the name's length";
    }
  }
  return nullptr;
}

}  // namespace

int main()
{
  netif_posix_add(NETIF_IPADDR, NETIF_NETMASK);
  osKernelStart();
  mros2::init(0, NULL);
  mros2::Node node = mros2::Node::create_node("service_pair");
  node.create_service<rcl_interfaces::srv::GetParameterTypes>("parameter_types", name_lengths);
  mros2::Client client = node.create_client<rcl_interfaces::srv::GetParameterTypes>("name_lengths");
  printf("app ready\n");
  fflush(stdout);

  while (!client.service_is_ready()) {
    osDelay(100);
  }
  printf("service ready\n");
  fflush(stdout);
  for (int i = 0; i < CALLS; ++i) {
    GetParameterTypes::Request request;
    request.names.push_back("call " + std::to_string(i));
    request.names.push_back(std::string(i, 'x'));
    GetParameterTypes::Response response;
    const char *wrong = nullptr;
    if (!client.call(request, response, CALL_TIMEOUT_MS)) {
      wrong = "no reply";
    } else {
      wrong = check_reply(request, response);
    }
    if (wrong) {
      printf("call %d failed: %s\n", i, wrong);
    } else {
      printf("call %d ok\n", i);
    }
    fflush(stdout);
  }
  printf("calls done\n");
  fflush(stdout);
  mros2::spin();
  return 0;
}
