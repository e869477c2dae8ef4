# SPDX-License-Identifier: BSD-3-Clause
"""The rule table: what a message type needs of each mROS v1 library setting.

The library keeps each TCPROS connection header a ROS node sends in a
buffer of fixed size, copies each type name into a field of fixed size and
takes each message from memory pools of fixed sizes, and checks none of them
against what a peer sends (docs/pc-target.md, "The library's own limits").
Each :class:`Rule` here is one such need, counted from what genmros
knows of a type (:class:`TypeNeeds`: its full definition text, its name, its
largest frame); :data:`FRAME_SLOTS` is the one rule of the firmware as a
whole. The Python fit check (:mod:`.fit`) and the compile-time check
``mros_v1_fit_check.h`` (:mod:`.fit_check_header`) are two renderings of
this one table, and on-board delivery (``mros_v1_delivery.h``) takes its
defaults from here.

A connection header's length depends on the *names* too, the topic and the
peer's caller id, which the firmware's code and the ROS side choose: with
the shortest names (``/a``) a header is certain to be that long; with a
topic of ``MROS_TOPIC_NAME_MAXLEN`` bytes and a caller id of
:data:`PEER_NAME_MAX` it can be that long. A setting too small even for the
shortest names is an error; one that fits only short names, a warning.
"""

# Field names, lengths, MD5 sum and flag of the TCPROS connection headers
# ROS nodes send, besides topic, type, caller id and definition text
# (measured against real rospy and roscpp nodes by tests/mros_v1/test_fit.py).
SUBSCRIBER_HEADER_FIXED = 115  # rospy's subscriber; roscpp's sends no definition text
PUBLISHER_HEADER_FIXED = 112  # roscpp's and rospy's reply to a subscriber
# The longest caller id of a ROS peer the check allows for: a node name in a
# namespace with rospy's anonymous suffix (_<pid>_<milliseconds>) fits.
PEER_NAME_MAX = 64
# The shortest topic and caller id: '/a' each.
SHORTEST_NAMES = 4
# MROS_TOPIC_RAWDATA_HEADER_SIZE: the library's header before each frame in a pool block.
FRAME_HEADER_SIZE = 4

# The headers that set the library's settings, in the order the build
# includes them: the app's (or the library's default) and the library's.
USR_CONFIG = 'mros_usr_config.h'
PACKET_CONFIG = 'mros_packet_config.h'
SETTINGS_HEADERS = (USR_CONFIG, PACKET_CONFIG)
# The include guard of the library's api/ros.h: defined where ros.cpp
# includes message_headers.h, so the settings can be included there.
LIBRARY_HEADER_GUARD = '_ROS_H_'
REQUEST_BUFFER = 'MROS_PACKET_MAXSIZE_REQ_TCPROS'
REPLY_BUFFER = 'MROS_PACKET_MAXSIZE_RES_TCPROS'
TYPENAME_MAX = 'MROS_TOPIC_TYPENAME_MAXLEN'
TOPIC_NAME_MAX = 'MROS_TOPIC_NAME_MAXLEN'
# The tables a firmware's topics and peers take room in (reported, not checked).
TABLES = ('MROS_TOPIC_MAX_NUM', 'MROS_NODE_MAX_NUM', 'MROS_PUB_TOPIC_CONNECTOR_MAX_NUM',
          'MROS_SUB_TOPIC_CONNECTOR_MAX_NUM')
# The compile-time check looks at this many pools of each kind (the samples have 3).
MAX_POOLS = 8
# Defined by genmros' patch set in ros.cpp before it includes
# message_headers.h: the library passes delivery each frame's size.
LIBRARY_PASSES_FRAME_SIZE = 'MROS_LIBRARY_PASSES_FRAME_SIZE'
# The largest message delivery constructs on the subscriber task's stack
# (mros_v1_delivery.h); a larger one gets static storage of its type, so
# delivery's stack use stays below this and the frame's bookkeeping.
DELIVERY_ON_STACK_MAX = 128


class PoolKind:
    """The memory pools of one use: blocks of <prefix>MEMPOOL<n>_SIZE bytes,
    n up to <prefix>CONFIG_NUM. What a rule needs of it is its largest block."""

    def __init__(self, use, prefix, holds_macro):
        self.use = use
        self.holds_macro = holds_macro  # mros_v1_fit_check.h's test: a block of n bytes?
        self.count = prefix + 'CONFIG_NUM'
        self.blocks = [(index, prefix + 'MEMPOOL%d_SIZE' % index)
                       for index in range(1, MAX_POOLS + 1)]
        self.sizes = [name for _, name in self.blocks]
        self.name = prefix + 'MEMPOOL<n>_SIZE'
        # How many blocks each pool has.
        self.queue_lengths = [(index, prefix + 'MEMPOOL%d_QUELEN' % index)
                              for index in range(1, MAX_POOLS + 1)]
        self.queue_length_name = prefix + 'MEMPOOL<n>_QUELEN'


PUBLISHING_POOLS = PoolKind('publishing', 'ROS_INNER_TOPIC_PUBLISHER_',
                            'MROS_FIT_PUBLISHING_POOL_HOLDS')
RECEIVING_POOLS = PoolKind('receiving from ROS nodes', 'ROS_OUTER_TOPIC_PUBLISHER_',
                           'MROS_FIT_RECEIVING_POOL_HOLDS')
POOL_KINDS = (PUBLISHING_POOLS, RECEIVING_POOLS)


class TypeNeeds:
    """The numbers of one message type the rules count with, from the
    ROS 1 front end's model of it."""

    def __init__(self, message):
        self.full_name = message.full_name
        self.type_name_size = len(message.full_name.encode('utf-8')) + 1  # with its NUL
        self.text_bytes = len(message.full_definition.encode('utf-8'))
        # The headers without the names (topic and caller id).
        type_fields = self.text_bytes + len(message.full_name.encode('utf-8'))
        self.subscriber_header = SUBSCRIBER_HEADER_FIXED + type_fields + 1  # the NUL after it
        self.publisher_header = PUBLISHER_HEADER_FIXED + type_fields
        self.max_frame = message.max_size
        self.pool_block = (None if message.max_size is None
                           else message.max_size + FRAME_HEADER_SIZE)
        self.unbounded_reason = message.unbounded_reason


class Rule:
    """One need of a type against one setting (a #define's name, or a
    PoolKind: its largest block), defined in the settings header `header`.

    amount(needs): the bytes the type needs without the names (None: no
    largest size, a frame in heap storage); with_names: a topic and a caller
    id come on top. what says what needs the setting ({max_frame}: the
    type's largest frame), in the error lines of both renderings; the Python
    check, which knows the settings' values, adds detail(needs, topic_max)."""

    def __init__(self, setting, header, amount, what, with_names=False, detail=None):
        self.setting = setting
        self.header = header
        self.amount = amount
        self.what = what
        self.with_names = with_names
        self.detail = detail

    @property
    def is_pool(self):
        return isinstance(self.setting, PoolKind)

    @property
    def setting_name(self):
        return self.setting.name if self.is_pool else self.setting

    def describe(self, needs, topic_max=None):
        """What needs the setting; with topic_max (MROS_TOPIC_NAME_MAXLEN's
        value) in the detail the rule has."""
        what = self.what.format(max_frame=needs.max_frame)
        if self.detail and topic_max is not None:
            what += ' ' + self.detail(needs, topic_max)
        return what

    def certain(self, needs):
        """The bytes the type needs for certain: with the shortest names
        where names count; None where it has no largest size."""
        amount = self.amount(needs)
        if amount is None:
            return None
        return amount + (SHORTEST_NAMES if self.with_names else 0)


class FrameSlotsRule:
    """The firmware's one rule of the library as a whole: where the library
    passes delivery no frame size (LIBRARY_PASSES_FRAME_SIZE undefined),
    mros_v1_delivery.h remembers the size of each frame published on the
    board, in `setting` slots (`default` unless the firmware defines it),
    and every block of the publishing pools can hold a frame waiting for the
    subscriber task at once."""

    setting = 'MROS_ONBOARD_FRAME_SLOTS'
    default = 32
    pools = PUBLISHING_POOLS

    def blocks(self, settings):
        """How many blocks the publishing pools have, from {name: Setting}
        (:mod:`colcon_mros.core.settings`), and the settings that say so."""
        count = settings[self.pools.count]
        lengths = [settings[name] for index, name in self.pools.queue_lengths
                   if index <= count.value and name in settings]
        return sum(length.value for length in lengths), [count] + lengths

    def slots(self, settings):
        """The slots: the firmware's Setting, or None (then `default`)."""
        return settings.get(self.setting)


FRAME_SLOTS = FrameSlotsRule()

RULES = (
    Rule(REQUEST_BUFFER, PACKET_CONFIG, lambda needs: needs.subscriber_header,
         "a ROS subscriber's connection header", with_names=True,
         detail=lambda needs, topic_max: (
             '(definition text %d bytes, a topic of up to %d and a caller id of up to %d, and '
             'the NUL)' % (needs.text_bytes, topic_max, PEER_NAME_MAX))),
    Rule(REPLY_BUFFER, PACKET_CONFIG, lambda needs: needs.publisher_header,
         "a ROS publisher's connection header", with_names=True),
    Rule(TYPENAME_MAX, USR_CONFIG, lambda needs: needs.type_name_size, 'its name with its NUL'),
    # The library checks a type name against the topic name's length too.
    Rule(TOPIC_NAME_MAX, USR_CONFIG, lambda needs: needs.type_name_size, 'its name with its NUL'),
    Rule(PUBLISHING_POOLS, USR_CONFIG, lambda needs: needs.pool_block,
         'a frame of up to {max_frame} bytes, %s,' % PUBLISHING_POOLS.use),
    Rule(RECEIVING_POOLS, USR_CONFIG, lambda needs: needs.pool_block,
         'a frame of up to {max_frame} bytes, %s,' % RECEIVING_POOLS.use),
)


class FirmwareNeeds:
    """The needs of a firmware's message types, and the largest of each."""

    def __init__(self, messages):
        self.types = [TypeNeeds(message) for message in messages]
        self.subscriber_header = max([t.subscriber_header for t in self.types] or [0])
        self.publisher_header = max([t.publisher_header for t in self.types] or [0])
        self.type_name_size = max([t.type_name_size for t in self.types] or [0])
        bounded = [t.pool_block for t in self.types if t.pool_block is not None]
        self.pool_block = max(bounded or [0])
        self.has_unbounded = len(bounded) < len(self.types)
