/* Stubs of mROS v1's C library for the footprint benchmark: one topic, one
 * block, and delivery of the published block to the subscriber, as the real
 * library delivers on-board frames. Counted in the baseline. */
#include "library.h"

static char block[4096];
static const char* volatile registered[4];
static int topic_type_id;
static void (*topic_callback)(void*);
static unsigned published;

void* library_topic(const char* name, const char* type, int type_id, const char* md5sum,
                    const char* definition) {
  registered[0] = name;
  registered[1] = type;
  registered[2] = md5sum;
  registered[3] = definition;
  topic_type_id = type_id;
  return block;
}

void library_subscribe(void* topic, void (*callback)(void*)) {
  (void)topic;
  topic_callback = callback;
}

char* library_alloc_block(void* topic, unsigned size) {
  (void)topic;
  return size <= sizeof block ? block : 0;
}

void library_publish(void* topic, char* data, unsigned size) {
  (void)topic;
  (void)data;
  published = size;
}

void library_run(void) {
  if (published && topic_callback) api_deliver(topic_type_id, topic_callback, block);
}
