/* SPDX-License-Identifier: BSD-3-Clause */
/* The C library under the API layer (mros-lib's node, topic, connector and
 * protocol code), reduced to the calls ros.cpp makes: stubs in library.c. */
#ifndef BENCH_FOOTPRINT_LIBRARY_H
#define BENCH_FOOTPRINT_LIBRARY_H

#ifdef __cplusplus
extern "C" {
#endif

typedef int library_return;
enum { LIBRARY_OK = 0 };

void library_lock(void);
void library_unlock(void);
library_return library_node_id(unsigned* node_id);
library_return library_topic_create(const char* name, const char* type, unsigned* topic_id);
library_return library_topic_set_typeid(unsigned topic_id, unsigned type_id);
library_return library_topic_set_definition(unsigned topic_id, const char* definition);
library_return library_topic_get_typeid(unsigned topic_id, unsigned* type_id);
library_return library_topic_set_md5sum(unsigned topic_id, const char* md5sum);
void* library_connector_manager(int subscriber);
library_return library_connector_add(void* manager, unsigned node_id, unsigned topic_id,
                                     void (*callback)(void*), int queue_size);
void* library_connector_object(void* manager, unsigned node_id, unsigned topic_id);
void library_register_with_master(void* object, int subscriber);
library_return library_alloc_data(void* object, char** block, unsigned size);
void library_wake_publisher(void);
void library_log_error(const char* file, const char* function, unsigned line, library_return ret);
void library_run(void);

/* Defined by the API layer: the library hands it every frame to deliver. */
void api_deliver(unsigned type_id, void (*callback)(void*), const char* block, unsigned size);

#ifdef __cplusplus
}
#endif

#endif
