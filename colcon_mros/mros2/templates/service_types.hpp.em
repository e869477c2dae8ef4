@# SPDX-License-Identifier: BSD-3-Clause
@# A service's halves, and the service naming them as rosidl's C++ does.
@(request_text)
@(response_text)
struct @(srv.name)
{
  typedef @(srv.request.name) Request;
  typedef @(srv.response.name) Response;
};
