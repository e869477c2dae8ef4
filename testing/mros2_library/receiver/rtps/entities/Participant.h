// SPDX-License-Identifier: BSD-3-Clause
// A stand-in of embeddedRTPS' Participant as its receiver uses it (the names
// and signatures are embeddedRTPS'): readers found by their entity id, or by a
// writer they are matched with.
#ifndef RTPS_PARTICIPANT_H
#define RTPS_PARTICIPANT_H

#include <vector>

#include "rtps/entities/Reader.h"
#include "rtps/entities/Writer.h"

namespace rtps {
class Participant {
 public:
  GuidPrefix_t m_guidPrefix;
  std::vector<Reader*> readers;

  Writer* getWriter(EntityId_t) const { return nullptr; }
  Reader* getReader(EntityId_t id) const {
    for (size_t i = 0; i < readers.size(); ++i)
      if (readers[i]->m_attributes.endpointGuid.entityId == id) return readers[i];
    return nullptr;
  }
  Reader* getReaderByWriterId(const Guid_t& guid) const {
    for (size_t i = 0; i < readers.size(); ++i)
      if (readers[i]->knowWriterId(guid)) return readers[i];
    return nullptr;
  }
  void addHeartbeat(GuidPrefix_t) {}
};
}  // namespace rtps

#endif  // RTPS_PARTICIPANT_H
