// SPDX-License-Identifier: BSD-3-Clause
// A stand-in of embeddedRTPS' rtps/discovery/BuiltInEndpoints.h: what the
// receiver's header takes of it is MessageTypes.h, which the real one
// includes through the entities.
#ifndef RTPS_BUILTINENDPOINTS_H
#define RTPS_BUILTINENDPOINTS_H

#include "rtps/messages/MessageTypes.h"

#endif  // RTPS_BUILTINENDPOINTS_H
