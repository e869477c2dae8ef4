# SPDX-License-Identifier: BSD-3-Clause
"""A firmware's endpoints: what it publishes and subscribes to.

An endpoint is a direction, a topic and a message type (the ROS 2 model's),
given as ``TOPIC:TYPE``, or a type alone where the topic is not known (the
headers and templates.hpp need only the type; the fit check then skips the
topic rules and counts one endpoint per type).
"""

from colcon_mros.errors import GenmrosError
from colcon_mros.mros2.cpp import CppMessageName

PUBLISH = 'publish'
SUBSCRIBE = 'subscribe'


class Endpoint:
    """A publisher or subscriber: its direction, topic (None where only the
    type was given), message and the message's C++ and DDS names."""

    def __init__(self, direction, topic, message):
        self.direction = direction
        self.topic = topic
        self.message = message
        self.wire_name = CppMessageName(message)

    def describe(self):
        topic = '(topic not given)' if self.topic is None else self.topic
        return '%s %s %s' % (self.direction, topic, self.message.full_name)


def split_endpoint(text):
    """'TOPIC:TYPE' -> (topic, type); 'TYPE' -> (None, type). ROS names
    have no ':', so the first one separates them; a leading '/' is the
    root namespace mros2 leaves out."""
    topic, colon, type_name = text.partition(':')
    if not colon:
        return None, text
    if not topic.strip('/') or not type_name:
        raise GenmrosError("'%s' is not TOPIC:TYPE or TYPE" % text)
    return topic.lstrip('/'), type_name


def topics_known(endpoints):
    return all(e.topic is not None for e in endpoints)


def count(endpoints, direction):
    """How many endpoints of a direction: one per topic where the topics
    are known, else at least one per type."""
    chosen = [e for e in endpoints if e.direction == direction]
    return len({(e.topic, e.message.full_name) if e.topic is not None else e.message.full_name
                for e in chosen})


def messages(endpoints, direction):
    """The distinct messages of a direction's endpoints, in their order."""
    found = {}
    for endpoint in endpoints:
        if endpoint.direction == direction:
            found.setdefault(endpoint.message.full_name, endpoint.message)
    return list(found.values())
