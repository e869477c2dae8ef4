# SPDX-License-Identifier: BSD-3-Clause
"""The rule table: what a firmware's endpoints need of its board's mros2 settings.

mros2 runs on embeddedRTPS, which keeps its endpoints, names and threads in
room fixed by the board's ``rtps/config.h`` (namespace ``rtps::Config``) and
checks a name only after copying it (``Domain::createWriter`` lets a name of
exactly ``MAX_*NAME_LENGTH`` bytes through and ``strcpy`` writes its NUL past
the field). Each :class:`Requirement` here is one need of one endpoint, type
or the firmware as a whole, counted from what genmros knows of it. The
Python fit check (:mod:`.fit`) compares the numbers with the settings it
reads; mros2's ``templates.hpp`` (:mod:`.render`) renders the same
requirements as ``static_assert``s on ``rtps::Config``, which is where the
one need Python cannot count lives: a subscribed message on the reader
thread's stack, whose ``sizeof`` only the target's compiler knows.
"""

from colcon_mros.mros2.cpp import CppMessageName
from colcon_mros.mros2.endpoints import PUBLISH, SUBSCRIBE, count, messages, topics_known

# rtps::Config's settings the rules read (rtps/config.h).
CONFIG_HEADER = 'rtps/config.h'
TYPENAME_MAX = 'MAX_TYPENAME_LENGTH'
TOPICNAME_MAX = 'MAX_TOPICNAME_LENGTH'
WRITERS_PER_PARTICIPANT = 'NUM_WRITERS_PER_PARTICIPANT'
READERS_PER_PARTICIPANT = 'NUM_READERS_PER_PARTICIPANT'
STATELESS_WRITERS = 'NUM_STATELESS_WRITERS'
STATELESS_READERS = 'NUM_STATELESS_READERS'
STATEFUL_WRITERS = 'NUM_STATEFUL_WRITERS'
STATEFUL_READERS = 'NUM_STATEFUL_READERS'
STATEFUL_HISTORY = 'HISTORY_SIZE_STATEFUL'
READER_STACK = 'THREAD_POOL_READER_STACKSIZE'
SETTINGS = (TYPENAME_MAX, TOPICNAME_MAX, WRITERS_PER_PARTICIPANT, READERS_PER_PARTICIPANT,
            STATELESS_WRITERS, STATELESS_READERS, STATEFUL_WRITERS, STATEFUL_READERS,
            STATEFUL_HISTORY, READER_STACK)

# mros2 names a topic's DDS endpoints 'rt/<topic>', as rmw does.
TOPIC_PREFIX = 'rt/'
# embeddedRTPS gives each participant a writer and a reader for SPDP, SEDP
# publications and SEDP subscriptions, out of its per-participant tables
# (Participant::addBuiltInEndpoints); mros2 makes one participant.
BUILTIN_ENDPOINTS = 3
# Of the domain's stateless (best-effort) writers and readers, the
# participant's SPDP writer and reader take one each; of its stateful
# (reliable) ones, its SEDP writers and readers (publications, subscriptions)
# two each. mros2 makes an endpoint stateless, unless the app asks for a
# reliable one (the mros2 patch reliable-where-asked).
BUILTIN_STATELESS = 1
BUILTIN_STATEFUL = 2
QOS_PATCH = 'reliable-where-asked'
# What the patched mros2.h defines, and templates.hpp and the fit check read.
QOS_MACRO = 'MROS2_RELIABLE_WHERE_ASKED'
# The mros2 patch node-in-the-ros-graph's writer: its topic and DDS type name, without
# mros2's topic prefix.
GRAPH_PATCH = 'node-in-the-ros-graph'
# The mros2 patch that serves and calls services, and what its mros2.h defines.
SERVICES_PATCH = 'services-both-ways'
SERVICES_MACRO = 'MROS2_SERVICES_BOTH_WAYS'
GRAPH_MACRO = 'MROS2_NODE_IN_THE_ROS_GRAPH'
GRAPH_TOPIC = 'ros_discovery_info'
GRAPH_TYPE = 'rmw_dds_common::msg::dds_::ParticipantEntitiesInfo_'
# What arrives in one datagram around a sample, as a Fast DDS or rmw writer
# sends a DATA to one reader: RTPS header 20, INFO_DST 16, INFO_TS 12, the
# DATA submessage's header and fields 24, the encapsulation header 4.
DATAGRAM_OVERHEAD = 20 + 16 + 12 + 24 + 4
# The largest SPDP announcement of a ROS 2 node measured here, the ROS 2 wheels' rclpy on
# Fast DDS 3 (544 to 572 bytes: it carries the host's name, the user's and the process id):
# a board whose network stack takes less discovers no such node.
DISCOVERY_ANNOUNCEMENT = 572
# The largest datagram the ROS side sends unless told otherwise: Fast DDS' UDP transport's
# maxMessageSize default. A larger sample goes out as DATA_FRAG submessages, each in a
# datagram of at most this.
PEER_MAX_MESSAGE = 65500
# The socket receive buffer genmros' Fast DDS profile gives a ROS 2 node: mros2 sends a
# large sample in fragments of 64 bytes (its frag_buf), some thousand datagrams for 64 KB,
# which the 208 KiB of Linux' default buffer does not hold (measured: 12 of 20 Images of
# 64 KB came back from a board; 20 of 20 with this).
PEER_RECEIVE_BUFFER = 4 * 1024 * 1024
# The mros2 patch that takes DATA_FRAG (library_tools/mros2/patches), the settings it adds
# to rtps::Config and its defaults where the board's config sets neither: no buffer.
DATA_FRAG_PATCH = 'data-frag-for-best-effort-readers'
FRAGMENT_BUFFER = 'FRAGMENT_BUFFER_SIZE'
FRAGMENT_BUFFERS = 'FRAGMENT_BUFFERS'
FRAGMENT_DEFAULTS = {FRAGMENT_BUFFER: 0, FRAGMENT_BUFFERS: 1}
# What a DATA_FRAG's sampleSize counts besides the CDR image: the encapsulation header.
ENCAPSULATION = 4
# What of the ROS side's largest message is not fragment: Fast DDS 3 (rclpy, the ROS 2
# wheels) sent fragments of 1296 bytes under a maxMessageSize of 1472, 3920 under 4096.
FRAGMENT_OVERHEAD = 176
# The reader thread's queue of received datagrams: the fragments of a sample that arrive
# while the thread is busy (in a callback, say) wait there, and those over it are dropped.
READER_QUEUE = 'THREAD_POOL_WORKLOAD_QUEUE_LENGTH'
# The reader thread's stack below the message: embeddedRTPS' receive path
# (the thread pool's loop, the domain, the participant, the message
# receiver, the reader) and mros2's callback frame besides its T msg. A
# firmware that measured its own (-fstack-usage) defines the macro.
READER_STACK_MARGIN = 512
READER_STACK_MARGIN_MACRO = 'MROS2_READER_STACK_MARGIN'


class Requirement:
    """One need: subject (a type, a topic, the firmware) needs setting
    >= needed, because of what. needed is None where only the target's
    compiler can count it; cpp_needed is the need as templates.hpp's
    static_assert spells it (by default, needed)."""

    def __init__(self, setting, subject, what, needed, cpp_needed=None):
        self.setting = setting
        self.subject = subject
        self.what = what
        self.needed = needed
        self.cpp_needed = cpp_needed or str(needed)
        # The static_assert's message: the misfit's line without the file
        # and the value the setting has.
        self.assertion_message = '%s: %s needs rtps::Config::%s >= %s (%s)' % (
            subject, what, setting, self.cpp_needed, CONFIG_HEADER)


def name_requirements(endpoints):
    """Each endpoint type's DDS type name and each topic's name, with NULs."""
    requirements = []
    names = {e.wire_name.dds_type_name: e.wire_name for e in endpoints}
    for name in sorted(names):
        requirements.append(Requirement(
            TYPENAME_MAX, name, 'its DDS type name and its NUL', names[name].dds_type_name_size))
    for topic in sorted({e.topic for e in endpoints if e.topic is not None}):
        requirements.append(Requirement(
            TOPICNAME_MAX, 'topic %s' % topic, "'%s%s' and its NUL" % (TOPIC_PREFIX, topic),
            len((TOPIC_PREFIX + topic).encode('utf-8')) + 1))
    return requirements


def _counted(endpoints, direction, kind, reliable=None):
    """The count of a direction's endpoints in words: the publishers or subscribers (kind),
    and the writers or readers of services and clients."""
    topics = [e for e in endpoints if e.service is None]
    services = [e for e in endpoints if e.service is not None]
    parts = []
    number = count(topics, direction, reliable)
    if number:
        how = 'one per topic' if topics_known(topics) else 'at least one per type'
        parts.append('%d %s%s (%s)' % (number, kind, '' if number == 1 else 's', how))
    number = count(services, direction, reliable)
    if number:
        noun = 'writer' if direction == PUBLISH else 'reader'
        parts.append('%d %s%s of services and clients (one each)'
                     % (number, noun, '' if number == 1 else 's'))
    return ' and '.join(parts)


def endpoint_count_requirements(endpoints, graph_writer=False):
    """The participant's writers and readers, and the domain's stateless and stateful
    ones (with graph_writer, GRAPH_PATCH's writer among them)."""
    requirements = []
    graph = ' and its writer on %s (the mros2 patch %s)' % (GRAPH_TOPIC, GRAPH_PATCH)
    for direction, kind, per_participant, stateless, stateful in (
            (PUBLISH, 'publisher', WRITERS_PER_PARTICIPANT, STATELESS_WRITERS,
             STATEFUL_WRITERS),
            (SUBSCRIBE, 'subscriber', READERS_PER_PARTICIPANT, STATELESS_READERS,
             STATEFUL_READERS)):
        extra = 1 if graph_writer and direction == PUBLISH else 0
        number = count(endpoints, direction)
        if number + extra:
            requirements.append(Requirement(
                per_participant, 'the firmware', "its %s%s and the participant's %d built-in "
                'ones (SPDP, SEDP publications, SEDP subscriptions)'
                % (_counted(endpoints, direction, kind), graph if extra else '',
                   BUILTIN_ENDPOINTS),
                number + extra + BUILTIN_ENDPOINTS))
        best_effort = count(endpoints, direction, reliable=False)
        if best_effort:
            requirements.append(Requirement(
                stateless, 'the firmware', "its %s, best-effort, and the participant's SPDP "
                'one' % _counted(endpoints, direction, kind, reliable=False),
                best_effort + BUILTIN_STATELESS))
        reliable = count(endpoints, direction, reliable=True)
        if reliable + extra:
            requirements.append(Requirement(
                stateful, 'the firmware', "its %s, reliable,%s and the participant's %d SEDP "
                'ones' % (_counted(endpoints, direction, kind, reliable=True),
                          graph if extra else '',
                          BUILTIN_STATEFUL), reliable + extra + BUILTIN_STATEFUL))
    return requirements


def history_requirements(endpoints):
    """Each reliable publisher's depth (a service's writer's too), which its stateful
    writer's history holds."""
    depths = {}
    for endpoint in endpoints:
        if endpoint.direction == PUBLISH and endpoint.reliable:
            subject = endpoint.service.describe() if endpoint.service else \
                'topic %s' % endpoint.topic
            depths[subject] = max(depths.get(subject, 0), endpoint.depth)
    return [Requirement(STATEFUL_HISTORY, subject, 'a reliable publisher keeping its last %d '
                        'samples' % depth, depth)
            for subject, depth in sorted(depths.items())]


def reader_stack_requirements(endpoints):
    """A subscribed message on the reader thread's stack (templates.hpp only)."""
    subscribed = [CppMessageName(message) for message in messages(endpoints, SUBSCRIBE)]
    return [Requirement(
        READER_STACK, name.cpp_name,
        "mros2's callback_handler holding the message on the reader thread's stack, with %s "
        'bytes for the frames below it' % READER_STACK_MARGIN_MACRO,
        None, 'sizeof(%s) + %s' % (name.cpp_name, READER_STACK_MARGIN_MACRO))
        for name in subscribed]


def requirements(endpoints, graph_writer=False):
    """Every requirement of a firmware's endpoints; graph_writer: with the mros2 patch
    GRAPH_PATCH's writer too, which mros2 makes before them."""
    return (name_requirements(endpoints) +
            endpoint_count_requirements(endpoints, graph_writer) +
            history_requirements(endpoints) + reader_stack_requirements(endpoints))


def graph_type_name_requirement():
    """GRAPH_PATCH's type name, without room for which mros2 makes no writer on GRAPH_TOPIC
    and the board runs unlisted in the ROS 2 graph (nothing else fails)."""
    return Requirement(TYPENAME_MAX, GRAPH_TYPE, 'its DDS type name and its NUL (the writer '
                       'on %s of the mros2 patch %s, without which ROS 2 does not list the '
                       "board's node)" % (GRAPH_TOPIC, GRAPH_PATCH), len(GRAPH_TYPE) + 1)


def graph_writer_requirements(endpoints):
    """The requirements the mros2 patch GRAPH_PATCH's writer adds or makes larger."""
    without = {requirement.assertion_message for requirement in requirements(endpoints)}
    return [requirement for requirement in requirements(endpoints, graph_writer=True)
            if requirement.assertion_message not in without]


def largest_datagram(message):
    """The most bytes a sample of message takes in one datagram (None:
    no largest): the image padded to 4, as mros2 and Fast DDS send it,
    and the RTPS submessages around it."""
    if message.max_size is None:
        return None
    return DATAGRAM_OVERHEAD + message.max_size + (-message.max_size % 4)


def discovery_problem(option, largest_message):
    """The error for a ROS side whose largest message (given as option) is below
    DISCOVERY_ANNOUNCEMENT, or None."""
    if largest_message >= DISCOVERY_ANNOUNCEMENT:
        return None
    return ("%s %d: below %d bytes, a ROS 2 node's SPDP announcement as Fast DDS 3 sends it: "
            'the board would discover no such node'
            % (option, largest_message, DISCOVERY_ANNOUNCEMENT))


def largest_serialized_sample(message):
    """A DATA_FRAG's largest sampleSize for message: the encapsulation and the image
    padded to 4."""
    return ENCAPSULATION + message.max_size + (-message.max_size % 4)


def fragmented(endpoints, peer_max_message):
    """The subscribed bounded messages whose largest sample the ROS side sends in fragments:
    its datagram would be over peer_max_message."""
    return [message for message in messages(endpoints, SUBSCRIBE)
            if message.max_size is not None and largest_datagram(message) > peer_max_message]


def data_frag_requirements(endpoints, peer_max_message):
    """With the patch DATA_FRAG_PATCH: each message the ROS side fragments, put together in
    a buffer of FRAGMENT_BUFFER_SIZE bytes, its fragments queued for the reader thread."""
    fragment = peer_max_message - FRAGMENT_OVERHEAD
    found = []
    for message in fragmented(endpoints, peer_max_message):
        sample = largest_serialized_sample(message)
        found.append(Requirement(
            FRAGMENT_BUFFER, message.full_name,
            'a sample of up to %d bytes and its encapsulation, put together from the fragments '
            'the ROS side sends (over --peer-max-message %d)' % (message.max_size,
                                                                 peer_max_message), sample))
        found.append(Requirement(
            READER_QUEUE, message.full_name,
            "the fragments of a sample of up to %d bytes (%d bytes each: --peer-max-message %d "
            "less %d), queued while the reader thread is busy" % (
                message.max_size, fragment, peer_max_message, FRAGMENT_OVERHEAD),
            -(-sample // fragment)))
    return found


# A ParticipantEntitiesInfo as the patch GRAPH_PATCH writes it, in CDR with its encapsulation:
# the participant's GID, one node in '/', then the readers' and writers' GIDs. Besides the
# GIDs and the node name's characters it takes at most this many bytes (the counts, '/',
# the name's length and NUL, up to 3 of padding).
GRAPH_SAMPLE_FIXED = 32
# The GID sizes rmw uses: from Iron on, and in Humble (RMW_GID_STORAGE_SIZE).
GID_SIZES = (16, 24)


def history_memory_lines(endpoints, history_size, graph_writer):
    """What the stateful writers' histories hold at most, in pbufs, as lines of the report:
    each reliable writer its depth of its largest sample, and (graph_writer) the writer on
    GRAPH_TOPIC its last history_size samples, the latest the largest."""
    lines = []
    for endpoint in endpoints:
        if endpoint.direction != PUBLISH or not endpoint.reliable:
            continue
        subject = endpoint.service.describe() if endpoint.service else \
            'topic %s' % endpoint.topic
        size = endpoint.message.max_size
        depth = endpoint.depth
        lines.append('%s: %d samples of %s' % (
            subject, depth, 'unbounded size' if size is None else
            'up to %d bytes: %d bytes' % (largest_serialized_sample(endpoint.message),
                                          depth * largest_serialized_sample(endpoint.message))))
    if graph_writer:
        gids = 1 + count(endpoints, PUBLISH) + count(endpoints, SUBSCRIBE)
        lines.append('the writer on %s (the mros2 patch %s): %d samples of up to %s bytes, N '
                     "the node name's length (a GID of %s bytes)" % (
                         GRAPH_TOPIC, GRAPH_PATCH, history_size, ' or '.join(
                             '%d + N' % (GRAPH_SAMPLE_FIXED + gids * gid) for gid in GID_SIZES),
                         ' or '.join(str(gid) for gid in GID_SIZES)))
    return lines
