# SPDX-License-Identifier: BSD-3-Clause
"""The fit check: a firmware's mros2 endpoints against its board's settings.

The endpoints are what the firmware publishes and subscribes to: a topic and
a type each, or a type alone (then the topic rules are skipped, and the
check says so). The settings are the board's ``rtps/config.h``
(:func:`colcon_mros.core.settings.read_settings`), the receive limit of its
network stack (a setting read from the port's headers, or a number given),
the largest datagram the ROS side sends (``--peer-max-message``: its
transport's setting, which nothing on the board can read), and, where the
user's mros2 checkout is known, whether its ``Publisher`` has a writer of
its own, whether it takes samples in fragments (the patch data-frag-for-
best-effort-readers), whether it makes reliable endpoints (reliable-where-
asked) and whether it writes ros_discovery_info (node-in-the-ros-graph),
whose writer counts with the firmware's. Each :mod:`.rules` requirement that
a setting does not meet is one line naming the setting, its file and line,
the value it needs and the value it has; a need only the target's compiler
can count is left to templates.hpp's static_asserts, rendered from the same
rules.
"""

import os
import re

from colcon_mros.core.settings import GivenSetting, misfit_line, read_settings
from colcon_mros.errors import GenmrosError, GenmrosProblems
from colcon_mros.mros2.endpoints import PUBLISH, SUBSCRIBE, count, messages, topics_known
from colcon_mros.mros2.rules import (CONFIG_HEADER, DATA_FRAG_PATCH, DISCOVERY_ANNOUNCEMENT,
                                     ENCAPSULATION, FRAGMENT_BUFFER, FRAGMENT_DEFAULTS,
                                     FRAGMENT_OVERHEAD, GRAPH_MACRO, PEER_MAX_MESSAGE,
                                     QOS_MACRO, QOS_PATCH, READER_QUEUE,
                                     SERVICES_MACRO, SERVICES_PATCH, SETTINGS,
                                     STATEFUL_HISTORY, TYPENAME_MAX,
                                     data_frag_requirements, discovery_problem,
                                     graph_type_name_requirement, history_memory_lines,
                                     largest_datagram, requirements)

# mros2's public header, where its Publisher class is declared.
MROS2_HEADER = os.path.join('include', 'mros2.h')
# embeddedRTPS' receiver, whose header declares the fragment buffers where the patch is in.
RECEIVER_HEADER = os.path.join('embeddedRTPS', 'include', 'rtps', 'messages',
                               'MessageReceiver.h')
_PUBLISHER_CLASS = re.compile(r'^\s*class\s+Publisher\s*(?:\{|$)')
_WRITER_MEMBER = re.compile(r'\brtps::Writer\s*\*\s*\w+\s*(?:=[^;]*)?;')
_FRAGMENT_BUFFER = re.compile(r'\b%s\b' % FRAGMENT_BUFFER)
_ADD_PATCH = ' (genmros mros2-harden)'


def _lines(path):
    try:
        with open(path, encoding='utf-8', errors='replace') as stream:
            return stream.read().splitlines()
    except OSError as error:
        raise GenmrosError('cannot read the mros2 checkout: %s' % error.strerror, path)


class Mros2Checkout:
    """What the fit check reads of the user's mros2: whether it gives each Publisher a
    writer of its own (has_writer; the class is at path, line), whether its
    embeddedRTPS takes samples in fragments (takes_data_frag), whether it makes reliable
    endpoints (has_qos), whether it writes ros_discovery_info (in_ros_graph) and whether it
    serves and calls services (has_services)."""

    def __init__(self, mros2_root):
        self.path = os.path.join(mros2_root, MROS2_HEADER)
        lines = _lines(self.path)
        self.takes_data_frag = any(_FRAGMENT_BUFFER.search(line)
                                   for line in _lines(os.path.join(mros2_root, RECEIVER_HEADER)))
        self.has_qos = any(QOS_MACRO in line for line in lines)
        self.in_ros_graph = any(GRAPH_MACRO in line for line in lines)
        self.has_services = any(SERVICES_MACRO in line for line in lines)
        starts = [number for number, line in enumerate(lines) if _PUBLISHER_CLASS.match(line)]
        if not starts:
            raise GenmrosError('declares no class Publisher; is this an mros2 checkout?',
                               self.path)
        self.line = starts[0] + 1
        body = []
        for line in lines[starts[0]:]:
            body.append(line)
            if line.strip().startswith('};'):
                break
        self.has_writer = bool(_WRITER_MEMBER.search('\n'.join(body)))


class Fit:
    """Endpoints against settings ({name: Setting} of the board's
    rtps/config.h); receive_limit: a Setting of the largest datagram the
    board's network stack takes, or None; checkout: an Mros2Checkout, or
    None where the mros2 checkout is not known; peer_max_message: the
    largest datagram the ROS side sends. misfits and warnings are the
    lines; notes say what was not checked, after name_notes (what the app
    must do with the topic names); board_requirements are the rules that
    hold for this board only, for templates.hpp."""

    def __init__(self, endpoints, settings, receive_limit=None, checkout=None,
                 name_notes=(), peer_max_message=PEER_MAX_MESSAGE):
        self.endpoints = endpoints
        self.settings = settings
        self.misfits = []
        self.warnings = []
        self.notes = list(name_notes)
        if not topics_known(endpoints):
            self.notes.append('topics not given for every endpoint (--publish/--subscribe '
                              'TOPIC:TYPE): topic names not checked, one endpoint counted per '
                              'type')
        problem = discovery_problem('--peer-max-message', peer_max_message)
        if problem:
            raise GenmrosError(problem)
        self.peer = GivenSetting("the ROS side's largest message", peer_max_message,
                                 '--peer-max-message %d' % peer_max_message)
        takes_data_frag = checkout is not None and checkout.takes_data_frag
        self.board_requirements = data_frag_requirements(
            endpoints, peer_max_message) if takes_data_frag else []
        graph_writer = checkout is not None and checkout.in_ros_graph
        self.graph_writer = graph_writer
        for requirement in requirements(endpoints, graph_writer) + self.board_requirements:
            if requirement.needed is None:  # templates.hpp's static_assert counts it
                continue
            setting = self._setting(requirement.setting)
            if setting.value < requirement.needed:
                self.misfits.append(misfit_line(setting, requirement.subject, requirement.what,
                                                requirement.needed))
        if graph_writer:
            self._check_graph_type_name()
        subscribed = messages(endpoints, SUBSCRIBE)
        self._check_receive_limit(subscribed, receive_limit, takes_data_frag)
        if subscribed and checkout is None:
            self.notes.append('whether this mros2 takes samples in fragments (the mros2 patch %s) '
                              'is not known here (--mros2-root): checked as without it'
                              % DATA_FRAG_PATCH)
        self._check_publishers(count(endpoints, PUBLISH), checkout)
        self._check_qos(checkout)

    def _setting(self, name):
        if name not in self.settings and name in FRAGMENT_DEFAULTS:
            return GivenSetting(name, FRAGMENT_DEFAULTS[name], '%s, which sets no %s (%s: %d)' % (
                self._setting(TYPENAME_MAX).path, name, DATA_FRAG_PATCH,
                FRAGMENT_DEFAULTS[name]))
        if name not in self.settings:
            raise GenmrosError('the board settings given define no %s (give the rtps/config.h '
                               'the firmware compiles with)' % name)
        return self.settings[name]

    def _check_receive_limit(self, subscribed, limit, takes_data_frag):
        """Each subscribed sample in the datagrams it comes in: one, or (with the patch, over
        the peer's largest message) fragments of up to that."""
        peer = self.peer.value
        if limit is None:
            if subscribed:
                self.notes.append('no receive limit given (--receive-limit): the largest '
                                  'samples not checked')
            if not takes_data_frag:
                return
        elif limit.value < DISCOVERY_ANNOUNCEMENT:
            self.warnings.append(
                "%s: %s %d is below %d bytes, a ROS 2 node's SPDP announcement as Fast DDS 3 "
                'sends it (measured; it grows with the host and user names): the board '
                'discovers no such node' % (limit.where(), limit.name, limit.value,
                                            DISCOVERY_ANNOUNCEMENT))
        if takes_data_frag:
            way_out = ("; or have the ROS side send it in fragments of at most that: its "
                       "transport's maxMessageSize and --peer-max-message (docs/mros2.md)")
        else:
            way_out = '; or apply the mros2 patch %s%s to take it in fragments' % (
                DATA_FRAG_PATCH, _ADD_PATCH)
        in_fragments = []
        for message in subscribed:
            datagram = largest_datagram(message)
            if datagram is None:
                self.warnings.append(self._unbounded(message, limit, takes_data_frag))
            elif datagram > peer and takes_data_frag:
                in_fragments.append(message.full_name)
            elif limit is not None and datagram > limit.value:
                self.misfits.append(misfit_line(
                    limit, message.full_name, 'a sample of up to %d bytes in one datagram, RTPS '
                    'around it' % message.max_size, datagram) + way_out)
            elif datagram > peer:
                self.misfits.append(misfit_line(
                    self.peer, message.full_name, 'a sample of up to %d bytes in one datagram, '
                    'RTPS around it' % message.max_size, datagram) +
                    '; the ROS side sends a larger one in fragments, which this mros2 skips: '
                    "raise its transport's maxMessageSize, or apply the mros2 patch %s%s"
                    % (DATA_FRAG_PATCH, _ADD_PATCH))
        if in_fragments and limit is not None and peer > limit.value:
            self.misfits.append(misfit_line(
                limit, 'the ROS side', 'its largest message (--peer-max-message %d), in which '
                'it sends %s in fragments,' % (peer, ', '.join(in_fragments)), peer) +
                "; or give the ROS side's transport a maxMessageSize of at most %d and "
                '--peer-max-message to match (docs/mros2.md)' % limit.value)

    def _unbounded(self, message, limit, takes_data_frag):
        """The warning for a subscribed message with no largest sample."""
        head = '%s: a sample has no largest size (unbounded): ' % message.full_name
        tail = '; bounded storage gives the exact need'
        if takes_data_frag:
            buffer = self._setting(FRAGMENT_BUFFER)
            lost = ''
            if limit is not None and self.peer.value > limit.value:
                lost = 'one of %d to %d bytes in one datagram is cut (%s %d), ' % (
                    limit.value + 1, self.peer.value, limit.name, limit.value)
            fragment = self.peer.value - FRAGMENT_OVERHEAD
            queue = self.settings.get(READER_QUEUE)
            taken = '' if queue is None else ': with %d and %d, up to %d bytes' % (
                buffer.value, queue.value,
                max(0, min(buffer.value, queue.value * fragment) - ENCAPSULATION))
            return '%s: %s%sone larger than %s %d less its encapsulation (%d) is refused and ' \
                'counted (mros2::Subscriber::refused_fragmented_samples); one of S bytes in ' \
                'fragments of %d (--peer-max-message %d less %d) needs %s >= S + %d and %s >= ' \
                '(S + %d) / %d, rounded up%s%s' % (
                    buffer.where(), head, lost, FRAGMENT_BUFFER, buffer.value, ENCAPSULATION,
                    fragment, self.peer.value, FRAGMENT_OVERHEAD, FRAGMENT_BUFFER,
                    ENCAPSULATION, READER_QUEUE, ENCAPSULATION, fragment, taken, tail)
        return '%s: %sone larger than %s %d does not arrive%s; or apply the mros2 patch %s%s ' \
            'to take it in fragments' % (limit.where(), head, limit.name, limit.value, tail,
                                         DATA_FRAG_PATCH, _ADD_PATCH)

    def _check_publishers(self, count, checkout):
        if count < 2:
            return
        if checkout is None:
            self.notes.append('%d publishers: whether this mros2 gives each its own writer is '
                              'not known here (--mros2-root)' % count)
        elif not checkout.has_writer:
            self.misfits.append(
                "%s:%d: the firmware: its %d publishers need a Publisher with a writer of its "
                "own; this mros2 sends every message through the last one created "
                "(mros2::pub_ptr): apply genmros' mros2 patch set (genmros mros2-harden)"
                % (checkout.path, checkout.line, count))

    def _check_graph_type_name(self):
        """A warning: the board works, unlisted."""
        requirement = graph_type_name_requirement()
        setting = self._setting(requirement.setting)
        if setting.value < requirement.needed:
            self.warnings.append(misfit_line(setting, requirement.subject, requirement.what,
                                             requirement.needed))

    def _check_qos(self, checkout):
        reliable = [e.describe() for e in self.endpoints if e.reliable]
        if checkout is None:
            if reliable:
                self.notes.append('whether this mros2 makes reliable endpoints (the mros2 patch '
                                  '%s) is not known here (--mros2-root): templates.hpp stops '
                                  'the build without it' % QOS_PATCH)
        elif reliable and not checkout.has_qos:
            self.misfits.append(
                '%s:%d: the firmware: its reliable endpoints (%s) need mros2 with the patch %s; '
                'this one makes every endpoint best-effort: apply genmros\' mros2 patch set '
                '(genmros mros2-harden)' % (checkout.path, checkout.line, ', '.join(reliable),
                                            QOS_PATCH))
        services = sorted({e.service.describe() for e in self.endpoints if e.service})
        if services and checkout is not None and not checkout.has_services:
            self.misfits.append(
                '%s:%d: the firmware: its services (%s) need mros2 with the patch %s: apply '
                "genmros' mros2 patch set (genmros mros2-harden)"
                % (checkout.path, checkout.line, ', '.join(services), SERVICES_PATCH))

    def refuse(self):
        """Raise the misfits as one error line each."""
        if self.misfits:
            raise GenmrosProblems(self.misfits)

    def report(self):
        """The report of ``genmros mros2-fit``: the endpoints and settings,
        then error, warning and note lines."""
        lines = ['| endpoint | DDS type name | largest sample |', '|---|---|---:|']
        for endpoint in self.endpoints:
            size = endpoint.message.max_size
            lines.append('| %s | %s | %s |' % (endpoint.describe(),
                                               endpoint.wire_name.dds_type_name,
                                               'unbounded' if size is None else size))
        lines.append('')
        lines.append('Settings (%s): %s' % (CONFIG_HEADER, ', '.join(
            '%s %d' % (name, self.settings[name].value)
            for name in SETTINGS if name in self.settings)))
        history = self.settings.get(STATEFUL_HISTORY)
        memory = history_memory_lines(self.endpoints, history.value if history else 0,
                                      self.graph_writer)
        if memory:
            lines.append('')
            lines.append("What the stateful writers' histories hold at most (pbufs):")
            lines += ['- %s' % line for line in memory]
        lines.append('')
        lines += ['error: %s' % line for line in self.misfits] or ['Every endpoint fits.']
        lines += ['warning: %s' % line for line in self.warnings]
        lines += ['note: %s' % line for line in self.notes]
        return '\n'.join(lines) + '\n'


def receive_limit(text):
    """The receive limit as given: a number (bytes), or FILE:NAME, a
    setting of the port's headers (a #define or a constant)."""
    if text is None:
        return None
    if text.isdigit():
        return GivenSetting('the receive limit', int(text), '--receive-limit %s' % text)
    path, colon, name = text.rpartition(':')
    if not colon or not path:
        raise GenmrosError("--receive-limit '%s' is neither a number of bytes nor FILE:NAME"
                           % text)
    settings = read_settings([path], "the receive limit's file (--receive-limit FILE:NAME)",
                             "give the port's header that sets NAME (lwipopts.h, say)")
    if name not in settings:
        raise GenmrosError('sets no number %s (--receive-limit)' % name, path)
    return settings[name]
