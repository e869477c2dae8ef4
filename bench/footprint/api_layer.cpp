// SPDX-License-Identifier: BSD-3-Clause
// The API layer of mROS v1 (mros-lib/mros-src/api/ros.cpp), call for call
// (the library's code, not copied: the same calls in the same order):
// subscribe() and advertise() register the topic, its type ID, definition
// and MD5 sum and a connector, logging every failure; publish() sizes a
// block with dataSize(), takes it from the pool and memCopy()s the body into
// it; received frames go through callCallback() from message_headers.h, with
// the frame's size where the library is patched to pass it; and
// message_class_specialization.h instantiates it all at the end. The C
// library under it is stubbed (library.c).
#include "ros.h"

#include "library.h"
#include "message_headers.h"

#define API_ERROR(ret) library_log_error(__FILE__, __FUNCTION__, __LINE__, ret)

// subscribe() and advertise() each register the topic, its type and a
// connector, as ros.cpp writes them: the same sequence in each template.
#define API_REGISTER_TOPIC(type, type_id, definition, subscriber, callback, queue_size, object) \
  do {                                                                                        \
    unsigned node_id;                                                                         \
    unsigned topic_id;                                                                        \
    unsigned registered_type_id;                                                              \
    library_lock();                                                                           \
    library_return ret = library_node_id(&node_id);                                           \
    if (ret != LIBRARY_OK) {                                                                  \
      library_unlock();                                                                       \
      API_ERROR(ret);                                                                         \
      break;                                                                                  \
    }                                                                                         \
    ret = library_topic_create(topic.c_str(), type, &topic_id);                               \
    if (ret != LIBRARY_OK) {                                                                  \
      library_unlock();                                                                       \
      API_ERROR(ret);                                                                         \
      break;                                                                                  \
    }                                                                                         \
    (void)library_topic_set_typeid(topic_id, type_id);                                        \
    (void)library_topic_set_definition(topic_id, definition);                                 \
    (void)library_topic_get_typeid(topic_id, &registered_type_id);                            \
    (void)library_topic_set_md5sum(topic_id, getMD5Sum(static_cast<int>(registered_type_id))); \
    void* manager = library_connector_manager(subscriber);                                    \
    if (manager == 0) {                                                                       \
      library_unlock();                                                                       \
      API_ERROR(ret);                                                                         \
      break;                                                                                  \
    }                                                                                         \
    ret = library_connector_add(manager, node_id, topic_id, callback, queue_size);            \
    if (ret != LIBRARY_OK) {                                                                  \
      library_unlock();                                                                       \
      API_ERROR(ret);                                                                         \
      break;                                                                                  \
    }                                                                                         \
    object = library_connector_object(manager, node_id, topic_id);                            \
    if (object == 0) {                                                                        \
      library_unlock();                                                                       \
      API_ERROR(ret);                                                                         \
      break;                                                                                  \
    }                                                                                         \
    library_register_with_master(object, subscriber);                                         \
    library_unlock();                                                                         \
  } while (0)

template <class T>
ros::Subscriber ros::NodeHandle::subscribe(std::string topic, int queue_size, void (*fp)(T)) {
  Subscriber subscriber;
  void* object = 0;
  API_REGISTER_TOPIC(message_traits::DataType<T>().value(), message_traits::DataTypeId<T>().value(),
                     message_traits::Definition<T>().value(), 1, reinterpret_cast<void (*)(void*)>(fp),
                     queue_size, object);
  subscriber.set(object);
  return subscriber;
}

template <class T> ros::Publisher ros::NodeHandle::advertise(std::string topic, int queue_size) {
  Publisher publisher;
  void* object = 0;
  API_REGISTER_TOPIC(message_traits::DataType<T*>().value(), message_traits::DataTypeId<T*>().value(),
                     message_traits::Definition<T*>().value(), 0, 0, queue_size, object);
  publisher.set(object);
  return publisher;
}

template <class T> void ros::Publisher::publish(T& data) {
  char* block;
  const unsigned size = static_cast<unsigned>(data.dataSize()) + 4;  // mros_protocol_get_buffersize
  library_lock();
  const library_return ret = library_alloc_data(get(), &block, size);
  if (ret != LIBRARY_OK) {
    API_ERROR(ret);
  } else {
    char* body = block + 4;  // mros_protocol_get_body
    data.memCopy(body);
  }
  library_unlock();
  library_wake_publisher();
}

// The library as it is gives delivery no frame size; with genmros' patch
// set (-DMROS_LIBRARY_PASSES_FRAME_SIZE, as its ros.cpp defines) it does.
extern "C" void api_deliver(unsigned type_id, void (*callback)(void*), const char* block,
                            unsigned size) {
#ifdef MROS_LIBRARY_PASSES_FRAME_SIZE
  callCallback(static_cast<int>(type_id), callback, const_cast<char*>(block), size);
#else
  (void)size;
  callCallback(static_cast<int>(type_id), callback, const_cast<char*>(block));
#endif
}

#include "message_class_specialization.h"
