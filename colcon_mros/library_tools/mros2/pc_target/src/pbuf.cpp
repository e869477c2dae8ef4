// SPDX-License-Identifier: BSD-3-Clause
// lwIP's pbufs (lwip/pbuf.h): each allocation one heap buffer, with lwIP's
// reference counting and chaining. The counts change atomically, as lwIP's
// do under SYS_ARCH_PROTECT: two threads may hold one pbuf.
#include <stdlib.h>
#include <string.h>

#include "lwip/pbuf.h"

extern "C" {

struct pbuf* pbuf_alloc(pbuf_layer, u16_t length, pbuf_type) {
  // The payload follows the header in one block, as lwIP's PBUF_RAM.
  struct pbuf* p = static_cast<struct pbuf*>(malloc(sizeof(struct pbuf) + length));
  if (p == NULL) return NULL;
  p->next = NULL;
  p->payload = p + 1;
  p->tot_len = length;
  p->len = length;
  p->ref = 1;
  return p;
}

u8_t pbuf_free(struct pbuf* p) {
  u8_t freed = 0;
  while (p != NULL && __atomic_sub_fetch(&p->ref, 1, __ATOMIC_ACQ_REL) == 0) {
    struct pbuf* next = p->next;
    free(p);
    freed++;
    p = next;
  }
  return freed;
}

void pbuf_ref(struct pbuf* p) {
  if (p != NULL) __atomic_add_fetch(&p->ref, 1, __ATOMIC_ACQ_REL);
}

void pbuf_cat(struct pbuf* head, struct pbuf* tail) {
  struct pbuf* p = head;
  for (; p->next != NULL; p = p->next) p->tot_len = (u16_t)(p->tot_len + tail->tot_len);
  p->tot_len = (u16_t)(p->tot_len + tail->tot_len);
  p->next = tail;
}

err_t pbuf_take_at(struct pbuf* buffer, const void* data, u16_t length, u16_t offset) {
  if (buffer == NULL || data == NULL || buffer->tot_len < offset + length) return ERR_MEM;
  const u8_t* from = static_cast<const u8_t*>(data);
  for (struct pbuf* p = buffer; p != NULL && length > 0; p = p->next) {
    if (offset >= p->len) {
      offset = (u16_t)(offset - p->len);
      continue;
    }
    u16_t here = (u16_t)(p->len - offset < length ? p->len - offset : length);
    memcpy(static_cast<u8_t*>(p->payload) + offset, from, here);
    from += here;
    length = (u16_t)(length - here);
    offset = 0;
  }
  return ERR_OK;
}

err_t pbuf_copy(struct pbuf* to, const struct pbuf* from) {
  if (to == NULL || from == NULL || to->tot_len < from->tot_len) return ERR_ARG;
  u16_t offset = 0;
  for (const struct pbuf* p = from; p != NULL; p = p->next) {
    pbuf_take_at(to, p->payload, p->len, offset);
    offset = (u16_t)(offset + p->len);
  }
  return ERR_OK;
}

}  // extern "C"
