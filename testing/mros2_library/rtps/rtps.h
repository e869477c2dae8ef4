// SPDX-License-Identifier: BSD-3-Clause
// A stand-in of what mros2's src/mros2.cpp and include/mros2.h use of
// embeddedRTPS (mROS-base/embeddedRTPS de70e01: rtps/rtps.h, the Domain,
// Participant, Writer and Reader entities and rtps/config.h), for a unit
// check of the real mros2.cpp on the host: a writer records what is
// published through it, with its topic and type name, and a reader keeps
// the callback mros2 registers so that the check can deliver samples. The
// network is left out; the names and signatures are embeddedRTPS'.
#ifndef MROS2_LIBRARY_STAND_IN_RTPS_H
#define MROS2_LIBRARY_STAND_IN_RTPS_H

#include <stdint.h>
#include <string.h>

#include <array>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace rtps {

typedef uint16_t DataSize_t;
typedef uint32_t FragDataSize_t;
enum class ChangeKind_t { ALIVE, NOT_ALIVE_DISPOSED };

// Endpoint identities, as embeddedRTPS' rtps/common/types.h has them.
struct GuidPrefix_t {
  std::array<uint8_t, 12> id;
};
enum class EntityKind_t : uint8_t {
  BUILD_IN_PARTICIPANT = 0xc1,
  USER_DEFINED_WRITER_WITHOUT_KEY = 0x03,
  USER_DEFINED_READER_WITHOUT_KEY = 0x04,
};
struct EntityId_t {
  std::array<uint8_t, 3> entityKey;
  EntityKind_t entityKind;
};
struct Guid_t {
  GuidPrefix_t prefix;
  EntityId_t entityId;
  bool operator==(const Guid_t& other) const {
    return prefix.id == other.prefix.id && entityId.entityKey == other.entityId.entityKey &&
           entityId.entityKind == other.entityId.entityKind;
  }
};
const Guid_t GUID_UNKNOWN{};
struct SequenceNumber_t {
  int32_t high;
  uint32_t low;
  bool operator==(const SequenceNumber_t& other) const {
    return high == other.high && low == other.low;
  }
};
const SequenceNumber_t SEQUENCENUMBER_UNKNOWN = {-1, 0};
struct SampleIdentity {
  Guid_t writerGuid;
  SequenceNumber_t sequenceNumber;
};
const EntityId_t ENTITYID_BUILD_IN_PARTICIPANT = {{{00, 00, 01}}, EntityKind_t::BUILD_IN_PARTICIPANT};
struct TopicData {
  Guid_t endpointGuid;
};
// The participant's prefix, and the next entity key of its endpoints.
const GuidPrefix_t STAND_IN_PREFIX = {{{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12}}};
uint8_t next_entity_key();

namespace Config {
const uint8_t MAX_TYPENAME_LENGTH = 64;
const uint8_t MAX_TOPICNAME_LENGTH = 64;
const uint8_t NUM_WRITERS_PER_PARTICIPANT = 16;
const uint8_t NUM_READERS_PER_PARTICIPANT = 16;
const uint8_t NUM_STATELESS_WRITERS = 16;
const uint8_t NUM_STATELESS_READERS = 16;
const uint8_t NUM_STATEFUL_WRITERS = 16;
const uint8_t NUM_STATEFUL_READERS = 16;
#ifdef STAND_IN_RMW_GID_STORAGE_SIZE
// A board's config that names its ROS 2's GID size (Humble: 24).
const uint8_t RMW_GID_STORAGE_SIZE = STAND_IN_RMW_GID_STORAGE_SIZE;
#endif
const int THREAD_POOL_READER_STACKSIZE = 8192;
const uint8_t HISTORY_SIZE_STATEFUL = 10;
}  // namespace Config

struct CacheChange {
  typedef std::pair<uint8_t*, DataSize_t> SerializedBuf;
  typedef std::function<SerializedBuf()> SerializerCallback;
  SequenceNumber_t sequenceNumber;
};

// One sample as a writer sent it.
struct Sent {
  std::string topic;
  std::string type_name;
  std::vector<uint8_t> bytes;
};
std::vector<Sent>& sent_samples();

class Writer {
 public:
  Writer(const char* topic, const char* type_name) : topic_(topic), type_name_(type_name) {
    m_attributes.endpointGuid = {STAND_IN_PREFIX,
                                 {{{0, 0, next_entity_key()}},
                                  EntityKind_t::USER_DEFINED_WRITER_WITHOUT_KEY}};
  }
  TopicData m_attributes;
  uint32_t getNumMatchedReader() { return 0; }
  const CacheChange* newChange(ChangeKind_t, const uint8_t* data, DataSize_t size) {
    record(std::vector<uint8_t>(data, data + size));
    return nullptr;
  }
  // As embeddedRTPS' writer thread does: fragments until the announced
  // size is out, then the call that ends the image.
  const CacheChange* newChangeCallback(ChangeKind_t, CacheChange::SerializerCallback func,
                                       FragDataSize_t size) {
    std::vector<uint8_t> bytes;
    while (bytes.size() < size) {
      CacheChange::SerializedBuf fragment = func();
      if (fragment.second == 0) break;
      bytes.insert(bytes.end(), fragment.first, fragment.first + fragment.second);
    }
    func();
    record(bytes);
    return nullptr;
  }

 private:
  void record(const std::vector<uint8_t>& bytes) {
    Sent sent = {topic_, type_name_, bytes};
    sent_samples().push_back(sent);
  }
  std::string topic_;
  std::string type_name_;
};

// A reliable writer (the patch reliable-where-asked sets how many samples it keeps).
class StatefulWriter : public Writer {
 public:
  using Writer::Writer;
  bool keepLast(uint16_t depth, uint32_t) { return depth != 0 && depth <= Config::HISTORY_SIZE_STATEFUL; }
  // The patch services-both-ways' write of a request or reply (its related
  // sample identity is not recorded).
  const CacheChange* newRelatedChange(const SampleIdentity&, const uint8_t* data,
                                      DataSize_t size) {
    return newChange(ChangeKind_t::ALIVE, data, size);
  }
};

class ReaderCacheChange {
 public:
  ReaderCacheChange(const uint8_t* data, DataSize_t size) : data_(data), size_(size) {}
  const uint8_t* getData() const { return data_; }
  const DataSize_t getDataSize() const { return size_; }
  const ChangeKind_t kind = ChangeKind_t::ALIVE;
  const Guid_t writerGuid{};
  const SequenceNumber_t sn{};
  bool hasRelatedIdentity = false;
  SampleIdentity relatedIdentity{};

 private:
  const uint8_t* data_;
  DataSize_t size_;
};

typedef void (*ddsReaderCallback_fp)(void* callee, const ReaderCacheChange& cacheChange);

class Reader {
 public:
  Reader() {
    m_attributes.endpointGuid = {STAND_IN_PREFIX,
                                 {{{0, 0, next_entity_key()}},
                                  EntityKind_t::USER_DEFINED_READER_WITHOUT_KEY}};
  }
  TopicData m_attributes;
  uint32_t getNumMatchedWriters() { return 0; }
  void registerCallback(ddsReaderCallback_fp cb, void* callee) {
    callback = cb;
    this->callee = callee;
  }
  // Delivers a sample as embeddedRTPS' reader thread does.
  void deliver(const uint8_t* data, DataSize_t size) {
    ReaderCacheChange change(data, size);
    callback(callee, change);
  }
  ddsReaderCallback_fp callback = nullptr;
  void* callee = nullptr;
};

// The patch data-frag-for-best-effort-readers' counts, which mros2's
// Subscriber shows.
struct FragmentCounts {
  uint32_t tooLarge, poolFull, inconsistent, abandoned, unmatched;
};
class MessageReceiver {
 public:
  static FragmentCounts fragmentCounts;
};

class Participant {
 public:
  GuidPrefix_t m_guidPrefix = STAND_IN_PREFIX;
  bool registerOnNewPublisherMatchedCallback(void (*)(void*), void*) { return true; }
  bool registerOnNewSubscriberMatchedCallback(void (*)(void*), void*) { return true; }
};

class Domain {
 public:
  bool completeInit() { return true; }
  Participant* createParticipant() { return &participant_; }
  Writer* createWriter(Participant&, const char* topic, const char* type_name, bool reliable) {
    writers_.push_back(reliable ? new StatefulWriter(topic, type_name)
                                : new Writer(topic, type_name));
    return writers_.back();
  }
  Reader* createReader(Participant&, const char*, const char*, bool) {
    readers().push_back(new Reader());
    return readers().back();
  }
  static std::vector<Reader*>& readers();

 private:
  Participant participant_;
  std::vector<Writer*> writers_;
};

}  // namespace rtps

#endif  // MROS2_LIBRARY_STAND_IN_RTPS_H
