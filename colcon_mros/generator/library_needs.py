"""What the mROS v1 library's settings must hold for a firmware's types.

The library keeps each TCPROS connection header a ROS node sends in a
buffer of fixed size, copies each type name into a field of fixed size and
takes each message from memory pools of fixed sizes, and checks none of them
against what a peer sends (docs/pc-target.md, "The library's own limits").
For each type a firmware uses this module computes what those settings need,
from what genmros knows of the type:

- the connection header a ROS node sends for it, exact in the type's fields
  (the full definition text, as roscpp and rospy send it whatever the
  firmware's headers carry; the type name; the MD5 sum), plus the topic and
  the peer's caller id: the *names*, which the firmware's code and the ROS
  side choose. With the shortest names (``/a``) a header is certain to be
  that long; with a topic of ``MROS_TOPIC_NAME_MAXLEN`` bytes and a caller
  id of :data:`PEER_NAME_MAX` it can be that long. A subscriber's header
  (rospy's, the longer: 115 bytes of field names, lengths, MD5 sum and
  ``tcp_nodelay``) is read into ``MROS_PACKET_MAXSIZE_REQ_TCPROS`` bytes with
  a NUL after it; a publisher's reply (112 bytes besides) into
  ``MROS_PACKET_MAXSIZE_RES_TCPROS``;
- the largest frame, exact where the type has a maximum, with the library's
  4-byte frame header, against the largest memory pool (publishing: the
  inner publisher pools; receiving from ROS nodes: the outer ones);
- the type name with its NUL, against ``MROS_TOPIC_TYPENAME_MAXLEN`` and
  (the library checks it there) ``MROS_TOPIC_NAME_MAXLEN``.

The values go into msg_max_size.h as macros, and into the compile-time
check ros.cpp includes (``mros_v1_fit_check.h``), where the library's own
settings are visible.
"""

# Field names, lengths, MD5 sum and flag of the TCPROS connection headers
# ROS nodes send, besides topic, type, caller id and definition text.
SUBSCRIBER_HEADER_FIXED = 115  # rospy's subscriber; roscpp's sends no definition text
PUBLISHER_HEADER_FIXED = 112  # roscpp's and rospy's reply to a subscriber
# The longest caller id of a ROS peer this check allows for: a node name in a
# namespace with rospy's anonymous suffix (_<pid>_<milliseconds>) fits.
PEER_NAME_MAX = 64
# The shortest topic and caller id: '/a' each.
SHORTEST_NAMES = 4
# MROS_TOPIC_RAWDATA_HEADER_SIZE: the library's header before each frame in a pool block.
FRAME_HEADER_SIZE = 4

# The library's settings, and the headers that define them.
SETTINGS_HEADERS = ('mros_usr_config.h', 'mros_packet_config.h')
REQUEST_BUFFER = 'MROS_PACKET_MAXSIZE_REQ_TCPROS'
REPLY_BUFFER = 'MROS_PACKET_MAXSIZE_RES_TCPROS'
TYPENAME_MAX = 'MROS_TOPIC_TYPENAME_MAXLEN'
TOPIC_NAME_MAX = 'MROS_TOPIC_NAME_MAXLEN'


# The compile-time check looks at this many pools of each kind (the samples have 3).
MAX_POOLS = 8


class PoolKind:
    """The memory pools of one use: blocks of <prefix>MEMPOOL<n>_SIZE bytes,
    n up to <prefix>CONFIG_NUM."""

    def __init__(self, use, prefix, holds_macro):
        self.use = use
        self.holds_macro = holds_macro  # mros_v1_fit_check.h's test: a block of n bytes?
        self.count = prefix + 'CONFIG_NUM'
        self.blocks = [(index, prefix + 'MEMPOOL%d_SIZE' % index)
                       for index in range(1, MAX_POOLS + 1)]
        self.sizes = [name for _, name in self.blocks]
        self.size_pattern = prefix + 'MEMPOOL<n>_SIZE'


POOL_KINDS = (PoolKind('publishing', 'ROS_INNER_TOPIC_PUBLISHER_', 'MROS_FIT_PUBLISHING_POOL_HOLDS'),
              PoolKind('receiving from ROS nodes', 'ROS_OUTER_TOPIC_PUBLISHER_',
                       'MROS_FIT_RECEIVING_POOL_HOLDS'))
# The tables a firmware's topics and peers take room in.
TABLES = ('MROS_TOPIC_MAX_NUM', 'MROS_NODE_MAX_NUM', 'MROS_PUB_TOPIC_CONNECTOR_MAX_NUM',
          'MROS_SUB_TOPIC_CONNECTOR_MAX_NUM')


class TypeNeeds:
    """What one message type needs of the library's settings."""

    def __init__(self, message):
        self.full_name = message.full_name
        self.type_name_size = len(message.full_name.encode('utf-8')) + 1  # with its NUL
        self.text_bytes = len(message.full_definition.encode('utf-8'))
        # The headers without the names (topic and caller id).
        type_fields = self.text_bytes + len(message.full_name.encode('utf-8'))
        self.subscriber_header = SUBSCRIBER_HEADER_FIXED + type_fields + 1  # the NUL after it
        self.publisher_header = PUBLISHER_HEADER_FIXED + type_fields
        self.max_frame = message.max_size
        self.pool_block = None if message.max_size is None else message.max_size + FRAME_HEADER_SIZE
        self.unbounded_reason = message.unbounded_reason

    def header_buffers(self, names):
        """(request, reply) bytes the header buffers need with a topic and a
        peer's caller id of names bytes together."""
        return self.subscriber_header + names, self.publisher_header + names


class LibraryNeeds:
    """The needs of a firmware's types, and the largest of each."""

    def __init__(self, messages):
        self.types = [TypeNeeds(message) for message in messages]
        self.subscriber_header = max([t.subscriber_header for t in self.types] or [0])
        self.publisher_header = max([t.publisher_header for t in self.types] or [0])
        self.type_name_size = max([t.type_name_size for t in self.types] or [0])
        bounded = [t.pool_block for t in self.types if t.pool_block is not None]
        self.pool_block = max(bounded or [0])
        self.bounded = [t for t in self.types if t.pool_block is not None]
        self.unbounded = [t for t in self.types if t.pool_block is None]
        self.peer_name_max = PEER_NAME_MAX
        self.shortest_names = SHORTEST_NAMES
        self.pool_kinds = POOL_KINDS
