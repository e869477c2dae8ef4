// SPDX-License-Identifier: BSD-3-Clause
// lwIP's packet buffers (lwip/pbuf.h): chains of reference-counted buffers.
// Here each pbuf_alloc gives one buffer from the heap, where the board's
// PBUF_POOL gives a chain of pool buffers of fixed size from a fixed pool.
#ifndef MROS2_PC_LWIP_PBUF_H
#define MROS2_PC_LWIP_PBUF_H

#include "lwip/err.h"

typedef enum { PBUF_TRANSPORT, PBUF_IP, PBUF_LINK, PBUF_RAW_TX, PBUF_RAW } pbuf_layer;
typedef enum { PBUF_RAM, PBUF_ROM, PBUF_REF, PBUF_POOL } pbuf_type;

struct pbuf {
  struct pbuf* next;
  void* payload;
  u16_t tot_len;  // this buffer's length and that of the rest of the chain
  u16_t len;
  u16_t ref;
};

#ifdef __cplusplus
extern "C" {
#endif
struct pbuf* pbuf_alloc(pbuf_layer layer, u16_t length, pbuf_type type);
u8_t pbuf_free(struct pbuf* p);
void pbuf_ref(struct pbuf* p);
void pbuf_cat(struct pbuf* head, struct pbuf* tail);
err_t pbuf_copy(struct pbuf* to, const struct pbuf* from);
err_t pbuf_take_at(struct pbuf* buffer, const void* data, u16_t length, u16_t offset);
#ifdef __cplusplus
}
#endif

#endif  // MROS2_PC_LWIP_PBUF_H
