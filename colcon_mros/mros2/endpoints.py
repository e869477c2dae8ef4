# SPDX-License-Identifier: BSD-3-Clause
"""A firmware's endpoints: what it publishes and subscribes to.

An endpoint is a direction, a topic and a message type (the ROS 2 model's),
given as ``TOPIC:TYPE``, or a type alone where the topic is not known (the
headers and templates.hpp need only the type; the fit check then skips the
topic rules and counts one endpoint per type). ``TOPIC:TYPE:reliable`` (or
``:reliable:DEPTH``) is one the app makes with ``mros2::QoS(DEPTH).reliable()``
(the mros2 patch reliable-where-asked); ``:best_effort``, as mros2 makes all.

A service the app serves or calls (the mros2 patch services-both-ways) is
``NAME:PKG/srv/TYPE``, and stands for the writer and reader mros2 makes for
it, as ROS 2 names them over DDS: requests on ``rq/NAMERequest``, replies on
``rr/NAMEReply``, both reliable and keeping ``SERVICE_DEPTH``. Their topics'
lengths are those of ``rt/`` names, which the rules count.

A topic is held to ROS 2's name rules as mros2 uses a name: it sends
``"rt/" + name`` as the app passes it and expands nothing, so a name ROS 2
refuses (or one it would expand) is one no ROS node ever matches.
"""

import re

from colcon_mros.errors import GenmrosError, GenmrosProblems
from colcon_mros.mros2.cpp import CppMessageName

PUBLISH = 'publish'
SUBSCRIBE = 'subscribe'
SERVE = 'serve'
CALL = 'call'
RELIABLE = 'reliable'
BEST_EFFORT = 'best_effort'
# The samples a reliable endpoint keeps where no depth is given: what mros2's
# examples pass, and rclcpp's default QoS keeps.
DEFAULT_DEPTH = 10
# What a service's writer and reader keep: rmw's services default, as the patch makes them.
SERVICE_DEPTH = 10


class Endpoint:
    """A publisher or subscriber: its direction, topic (None where only the
    type was given), message and the message's C++ and DDS names; whether it
    is reliable, and the samples it keeps (depth); for a service's writer or
    reader, the ServiceUse it serves."""

    def __init__(self, direction, topic, message, reliable=False, depth=DEFAULT_DEPTH,
                 service=None):
        self.direction = direction
        self.topic = topic
        self.message = message
        self.wire_name = CppMessageName(message)
        self.reliable = reliable
        self.depth = depth
        self.service = service

    def describe(self):
        if self.service is not None:
            return '%s (%s of %s)' % (self.service.describe(), self.direction,
                                      self.message.full_name)
        topic = '(topic not given)' if self.topic is None else self.topic
        qos = ' (reliable, depth %d)' % self.depth if self.reliable else ''
        return '%s %s %s%s' % (self.direction, topic, self.message.full_name, qos)


class ServiceUse:
    """A service the app serves or calls (role SERVE or CALL): its name (None where only
    the type was given) and its model."""

    def __init__(self, role, name, service):
        self.role = role
        self.name = name
        self.service = service

    def describe(self):
        return '%s %s %s' % (self.role, '(name not given)' if self.name is None else self.name,
                             self.service.full_name)

    def endpoints(self):
        """The writer and reader mros2 makes for it: a server reads requests and writes
        replies, a client the other way round."""
        def topic(suffix):
            return None if self.name is None else self.name + suffix
        request = (topic('Request'), self.service.request)
        reply = (topic('Reply'), self.service.response)
        written, read = (reply, request) if self.role == SERVE else (request, reply)
        return [Endpoint(PUBLISH, written[0], written[1], True, SERVICE_DEPTH, self),
                Endpoint(SUBSCRIBE, read[0], read[1], True, SERVICE_DEPTH, self)]


# What a ROS 2 name may hold besides '/' between its tokens.
_NAME_CHARACTER = re.compile(r'[A-Za-z0-9_/]')


def topic_name_problems(topic):
    """Why ROS 2 refuses topic as mros2 sends it (a leading '/' taken off
    already): the rules it breaks, or [] for a good name."""
    problems = []
    if '~' in topic:
        problems.append("'~' (mros2 expands no node namespace: write the name out)")
    if '{' in topic or '}' in topic:
        problems.append("'{}' (mros2 expands no substitution: write the name out)")
    others = sorted({c for c in topic if not _NAME_CHARACTER.match(c)} - set('~{}'))
    if others:
        problems.append('%s (a ROS 2 name holds only A-Z, a-z, 0-9, _ and /)'
                        % ', '.join(repr(c) for c in others))
    if '//' in topic:
        problems.append("'//' (an empty token)")
    digits = [token for token in topic.split('/') if token[:1].isdigit()]
    if digits:
        problems.append('%s starting with a digit' % ', '.join("'%s'" % t for t in digits))
    if topic.endswith('/'):
        problems.append("a trailing '/'")
    return problems


def split_endpoint(text):
    """'TOPIC:TYPE' -> (topic, type, notes); 'TYPE' -> (None, type, []).
    ROS names have no ':', so the first one separates them. A bad topic
    name is refused, with every rule it breaks; a leading '/' (the root
    namespace) is taken off, with a note that the app must do the same."""
    topic, colon, type_name = text.partition(':')
    if not colon:
        return None, text, []
    if not topic.strip('/') or not type_name:
        raise GenmrosError("'%s' is not TOPIC:TYPE or TYPE" % text)
    notes = []
    if topic.startswith('/'):
        notes.append("topic '%s': the app passes it to mros2 as '%s' (mros2 sends \"rt/\" and "
                     "the name as given: '%s' would go out as 'rt/%s', which no ROS node "
                     'matches)' % (topic, topic[1:], topic, topic))
        topic = topic[1:]
    problems = topic_name_problems(topic)
    if problems:
        raise GenmrosError("topic '%s' (in '%s'): ROS 2 refuses a name with %s, so no ROS node "
                           'would match it' % (topic, text, '; '.join(problems)))
    return topic, type_name, notes


def split_qos(text):
    """'TOPIC:TYPE:reliable[:DEPTH]' or 'TOPIC:TYPE:best_effort' -> ('TOPIC:TYPE', reliable,
    depth); a text with no QoS -> (text, False, DEFAULT_DEPTH)."""
    parts = text.split(':')
    depth = None
    if len(parts) > 2 and parts[-1].isdigit():
        depth = int(parts.pop())
    if parts[-1] not in (RELIABLE, BEST_EFFORT):
        if len(parts) > 2 or depth is not None:
            raise GenmrosError("'%s': '%s' is no QoS (reliable, reliable:DEPTH or best_effort)"
                               % (text, parts[-1] if depth is None else depth))
        return text, False, DEFAULT_DEPTH
    if len(parts) < 3:
        raise GenmrosError("'%s': a QoS needs the topic: TOPIC:TYPE:%s" % (text, parts[-1]))
    reliable = parts.pop() == RELIABLE
    if depth is not None and not reliable:
        raise GenmrosError("'%s': a depth goes with reliable (a best-effort endpoint keeps "
                           'no samples)' % text)
    if depth == 0:
        raise GenmrosError("'%s': a depth of 0 keeps nothing (1 or more)" % text)
    return ':'.join(parts), reliable, DEFAULT_DEPTH if depth is None else depth


def parse_endpoints(publish, subscribe, message_of, serve=(), call=(), service_of=None):
    """The Endpoints of --publish and --subscribe texts ('TOPIC:TYPE' or
    'TYPE'), their messages from message_of(type name), and of --serve and
    --call texts ('NAME:PKG/srv/TYPE' or the type), their services from
    service_of(type name); and the notes on their names. Every bad name is
    refused at once, one line each."""
    endpoints, notes, problems = [], [], []
    for direction, texts in ((PUBLISH, publish), (SUBSCRIBE, subscribe)):
        for text in texts:
            try:
                endpoint, reliable, depth = split_qos(text)
                topic, type_name, endpoint_notes = split_endpoint(endpoint)
            except GenmrosError as error:
                problems.append('--%s %s' % (direction, error))
                continue
            notes += endpoint_notes
            endpoints.append(Endpoint(direction, topic, message_of(type_name), reliable, depth))
    for role, texts in ((SERVE, serve), (CALL, call)):
        for text in texts:
            try:
                name, type_name, name_notes = split_endpoint(text)
            except GenmrosError as error:
                problems.append('--%s %s' % (role, error))
                continue
            notes += name_notes
            endpoints += ServiceUse(role, name, service_of(type_name)).endpoints()
    problems += _qos_conflicts(endpoints)
    if problems:
        raise GenmrosProblems(problems)
    return endpoints, notes


def _qos_conflicts(endpoints):
    """One line for each endpoint given twice with two QoS: mros2 makes one writer or reader
    per topic and type."""
    first, conflicts = {}, []
    for endpoint in endpoints:
        key = (endpoint.direction, endpoint.topic, endpoint.message.full_name)
        qos = (endpoint.reliable, endpoint.depth)
        if first.setdefault(key, qos) != qos:
            conflicts.append('--%s %s:%s: given with two QoS; mros2 makes one %s per topic and '
                             'type' % (endpoint.direction, endpoint.topic,
                                       endpoint.message.full_name,
                                       'writer' if endpoint.direction == PUBLISH else 'reader'))
    return conflicts


def topics_known(endpoints):
    return all(e.topic is not None for e in endpoints)


def count(endpoints, direction, reliable=None):
    """How many endpoints of a direction (of them, the reliable or the best-effort ones
    where reliable is True or False): one per topic where the topics are known, else at
    least one per type."""
    chosen = [e for e in endpoints if e.direction == direction and
              (reliable is None or e.reliable == reliable)]
    return len({(e.topic, e.message.full_name) if e.topic is not None else e.message.full_name
                for e in chosen})


def messages(endpoints, direction, of_services=True):
    """The distinct messages of a direction's endpoints (without a service's writers and
    readers where not of_services), in their order."""
    found = {}
    for endpoint in endpoints:
        if endpoint.direction == direction and (of_services or endpoint.service is None):
            found.setdefault(endpoint.message.full_name, endpoint.message)
    return list(found.values())


def services(endpoints, role):
    """The distinct services the app serves or calls (role SERVE or CALL), in their order."""
    found = {}
    for endpoint in endpoints:
        if endpoint.service is not None and endpoint.service.role == role:
            found.setdefault(endpoint.service.service.full_name, endpoint.service.service)
    return list(found.values())
