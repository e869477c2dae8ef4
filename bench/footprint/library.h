/* The C library under the API layer (mros-lib's topic and protocol code),
 * reduced to what the footprint benchmark calls: stubs in library.c. */
#ifndef BENCH_FOOTPRINT_LIBRARY_H
#define BENCH_FOOTPRINT_LIBRARY_H

#ifdef __cplusplus
extern "C" {
#endif

void* library_topic(const char* name, const char* type, int type_id, const char* md5sum,
                    const char* definition);
void library_subscribe(void* topic, void (*callback)(void*));
char* library_alloc_block(void* topic, unsigned size);
void library_publish(void* topic, char* block, unsigned size);
void library_run(void);

/* Defined by the API layer: the library hands it every frame to deliver. */
void api_deliver(int type_id, void (*callback)(void*), const char* block);

#ifdef __cplusplus
}
#endif

#endif
