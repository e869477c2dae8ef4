# SPDX-License-Identifier: BSD-3-Clause
"""The C++ names the mROS v1 headers own, handed to the core's escaping
(:mod:`colcon_mros.core.cpp_names`): members every message struct has,
names a header uses unqualified, the namespaces and declarations of the
support headers and of the aggregates' static headers, and their macros.
"""

from colcon_mros.core import cpp_names

# Members every generated message has (from mros::Message<T> and msg.h.em).
RESERVED_MEMBERS = frozenset('''
    serializedLength serialize deserialize dataSize memCopy Ptr ConstPtr
    MROS_TYPE_ID MROS_MIN_SERIALIZED_SIZE MROS_MAX_SERIALIZED_SIZE
'''.split())

# Names a message header uses unqualified inside the package's namespace
# and inside the message's struct: a member named like one would change
# what the next declaration means; a type named like one would hide it.
UNQUALIFIED_NAMES = frozenset('''
    int8_t uint8_t int16_t uint16_t int32_t uint32_t int64_t uint64_t size_t
    mros std
'''.split())

# Namespaces the generated headers (and the mROS v1 library) open, and the
# trait templates specialized there, looked up from inside them.
SUPPORT_NAMESPACES = frozenset('''
    mros std constants wire message_traits subtask_methods service_traits
    MD5Sum DataType DataTypeId Definition CallCallbackFuncs
'''.split())

# What the support header, and the static header an export of mROS v1
# aggregates puts beside it (colcon_mros.mros_v1.aggregates), declare in
# namespaces mros and mros::wire (types, templates, namespaces): message
# headers name packages from inside those namespaces, where these would be
# found first. tests/mros_v1/test_names.py holds this list equal to the headers'.
SUPPORT_HEADER_NAMES = frozenset('''
    CallCallbackFuncs Codec DataType DataTypeId Definition DeliveryStorage Duration ElementRun
    Fields FloatCodec IntegerCodec LengthCounter MD5Sum Message OnBoardFrames Reader
    RawStorage SequenceCodec Slots StampCodec TextCodec Time UnsignedWord Writer array
    bounded_string bounded_vector
    message_traits mros service_traits subtask_methods wire
'''.split())

# The macros the support headers define or read; a member so named is
# escaped like one of the standard headers' macros.
SUPPORT_MACROS = frozenset('''
    MROS_BOUNDED_OVERFLOW MROS_MESSAGE_CONTAINERS_H MROS_MESSAGE_SUPPORT_H
    MROS_MESSAGE_SUPPORT_VERSION MROS_MESSAGE_SUPPORT_VERSION_H MROS_MESSAGE_WIRE_H
    MROS_LIBRARY_PASSES_FRAME_SIZE MROS_ONBOARD_FRAME_SLOTS MROS_V1_DELIVERY_H MROS_WIRE_PORTABLE
'''.split())

# Members of a service's struct: a service cannot be named like one.
SERVICE_MEMBERS = frozenset(['Request', 'Response', 'request', 'response'])

RESERVED_NAMES = cpp_names.ReservedNames(
    members=RESERVED_MEMBERS | UNQUALIFIED_NAMES, macros=SUPPORT_MACROS,
    namespaces=SUPPORT_NAMESPACES | SUPPORT_HEADER_NAMES, service_members=SERVICE_MEMBERS)


def member_identifier(name, type_name):
    """The C++ spelling of a field or constant in an mROS v1 header."""
    return cpp_names.member_identifier(name, type_name, RESERVED_NAMES)
