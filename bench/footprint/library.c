/* SPDX-License-Identifier: BSD-3-Clause */
/* Stubs of mROS v1's C library for the footprint benchmark: one topic, one
 * block, and delivery of the published block to the subscriber, as the real
 * library delivers on-board frames. Counted in the baseline. */
#include "library.h"

static char block[4096];
static const char* volatile strings[4];
static unsigned topic_type_id;
static void (*topic_callback)(void*);
static unsigned published;
static volatile int locked;

void library_lock(void) { locked = 1; }
void library_unlock(void) { locked = 0; }

library_return library_node_id(unsigned* node_id) {
  *node_id = 1;
  return LIBRARY_OK;
}

library_return library_topic_create(const char* name, const char* type, unsigned* topic_id) {
  strings[0] = name;
  strings[1] = type;
  *topic_id = 1;
  return LIBRARY_OK;
}

library_return library_topic_set_typeid(unsigned topic_id, unsigned type_id) {
  (void)topic_id;
  topic_type_id = type_id;
  return LIBRARY_OK;
}

library_return library_topic_set_definition(unsigned topic_id, const char* definition) {
  (void)topic_id;
  strings[2] = definition;
  return LIBRARY_OK;
}

library_return library_topic_get_typeid(unsigned topic_id, unsigned* type_id) {
  (void)topic_id;
  *type_id = topic_type_id;
  return LIBRARY_OK;
}

library_return library_topic_set_md5sum(unsigned topic_id, const char* md5sum) {
  (void)topic_id;
  strings[3] = md5sum;
  return LIBRARY_OK;
}

void* library_connector_manager(int subscriber) { return subscriber ? (void*)&topic_callback : (void*)block; }

library_return library_connector_add(void* manager, unsigned node_id, unsigned topic_id,
                                     void (*callback)(void*), int queue_size) {
  (void)node_id;
  (void)topic_id;
  (void)queue_size;
  if (manager == (void*)&topic_callback) topic_callback = callback;
  return LIBRARY_OK;
}

void* library_connector_object(void* manager, unsigned node_id, unsigned topic_id) {
  (void)node_id;
  (void)topic_id;
  return manager;
}

void library_register_with_master(void* object, int subscriber) {
  (void)object;
  (void)subscriber;
}

library_return library_alloc_data(void* object, char** data, unsigned size) {
  (void)object;
  if (size > sizeof block) return 1;
  *data = block;
  published = size;
  return LIBRARY_OK;
}

void library_wake_publisher(void) {}

void library_log_error(const char* file, const char* function, unsigned line, library_return ret) {
  strings[0] = file;
  strings[1] = function;
  published = line + (unsigned)ret;
}

void library_run(void) {
  if (published && topic_callback) api_deliver(topic_type_id, topic_callback, block, published);
}
