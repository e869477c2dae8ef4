/* SPDX-License-Identifier: BSD-3-Clause */
/* Stand-in for lwIP's netdb.h: the one type mROS v1's headers name. */
#ifndef STUB_LWIP_NETDB_H
#define STUB_LWIP_NETDB_H
struct hostent {
  char* h_name;
  char** h_aliases;
  int h_addrtype;
  int h_length;
  char** h_addr_list;
};
#endif
