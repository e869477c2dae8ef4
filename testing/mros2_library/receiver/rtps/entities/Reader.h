// SPDX-License-Identifier: BSD-3-Clause
// A stand-in of embeddedRTPS' Reader and ReaderCacheChange as its receiver
// uses them (the names and signatures are embeddedRTPS'): a reader of a
// given reliability, matched with the writers it is given, that hands each
// sample it gets to the program's function.
#ifndef RTPS_READER_H
#define RTPS_READER_H

#include <vector>

#include "rtps/common/types.h"

namespace rtps {

struct SubmessageHeartbeat;

class ReaderCacheChange {
 public:
  const ChangeKind_t kind;
  const DataSize_t size;
  const Guid_t writerGuid;
  const SequenceNumber_t sn;
#ifdef RECEIVER_READS_INLINE_QOS
  // With the patch services-both-ways: what the receiver read of the inline QoS.
  bool hasRelatedIdentity = false;
  SampleIdentity relatedIdentity{};
  bool hasKeyHash = false;
  Guid_t keyHash{};
#endif

  ReaderCacheChange(ChangeKind_t kind, Guid_t& writerGuid, SequenceNumber_t sn,
                    const uint8_t* data, DataSize_t size)
      : kind(kind), size(size), writerGuid(writerGuid), sn(sn), data_(data) {}
  const uint8_t* getData() const { return data_; }

 private:
  const uint8_t* data_;
};

struct ReaderAttributes {
  Guid_t endpointGuid;
  ReliabilityKind_t reliabilityKind;
};

class Reader {
 public:
  ReaderAttributes m_attributes;

  typedef void (*Taker)(const Reader& reader, const ReaderCacheChange& change);

  Reader(const Guid_t& guid, ReliabilityKind_t reliability, const std::vector<Guid_t>& writers,
         Taker take)
      : m_attributes{guid, reliability}, writers_(writers), take_(take) {}

  void newChange(const ReaderCacheChange& change) { take_(*this, change); }
  bool onNewHeartbeat(const SubmessageHeartbeat&, const GuidPrefix_t&) { return true; }
  bool knowWriterId(const Guid_t& guid) const {
    for (size_t i = 0; i < writers_.size(); ++i)
      if (writers_[i] == guid) return true;
    return false;
  }

 private:
  std::vector<Guid_t> writers_;
  Taker take_;
};

}  // namespace rtps

#endif  // RTPS_READER_H
