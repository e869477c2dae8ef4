# SPDX-License-Identifier: BSD-3-Clause
"""The fit check: a firmware's mros2 endpoints against its board's settings.

The endpoints are what the firmware publishes and subscribes to: a topic
and a type each, or a type alone (then the topic rules are skipped, and the
check says so). The settings are the board's ``rtps/config.h``
(:func:`colcon_mros.core.settings.read_settings`), the receive limit of its
network stack (a setting read from the port's headers, or a number given),
and, where the user's mros2 checkout is known, whether its ``Publisher``
has a writer of its own. Each :mod:`.rules` requirement that a setting
does not meet is one line naming the setting, its file and line, the value
it needs and the value it has; a need only the target's compiler can count
is left to templates.hpp's static_asserts, rendered from the same rules.
"""

import os
import re

from colcon_mros.core.settings import GivenSetting, misfit_line, read_settings
from colcon_mros.errors import GenmrosError, GenmrosProblems
from colcon_mros.mros2.endpoints import PUBLISH, SUBSCRIBE, count, messages, topics_known
from colcon_mros.mros2.rules import (CONFIG_HEADER, DISCOVERY_ANNOUNCEMENT, SETTINGS,
                                     largest_datagram, requirements)

# mros2's public header, where its Publisher class is declared.
MROS2_HEADER = os.path.join('include', 'mros2.h')
_PUBLISHER_CLASS = re.compile(r'^\s*class\s+Publisher\s*(?:\{|$)')
_WRITER_MEMBER = re.compile(r'\brtps::Writer\s*\*\s*\w+\s*(?:=[^;]*)?;')


class PublisherWriter:
    """Whether the user's mros2 gives each Publisher a writer of its own
    (has_writer), read from its include/mros2.h, and where that class is."""

    def __init__(self, mros2_root):
        self.path = os.path.join(mros2_root, MROS2_HEADER)
        try:
            with open(self.path, encoding='utf-8', errors='replace') as stream:
                lines = stream.read().splitlines()
        except OSError as error:
            raise GenmrosError('cannot read the mros2 checkout: %s' % error.strerror, self.path)
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
    board's network stack takes, or None; publisher_writer: a
    PublisherWriter, or None where the mros2 checkout is not known.
    misfits and warnings are the lines; notes say what was not checked,
    after name_notes (what the app must do with the topic names)."""

    def __init__(self, endpoints, settings, receive_limit=None, publisher_writer=None,
                 name_notes=()):
        self.endpoints = endpoints
        self.settings = settings
        self.misfits = []
        self.warnings = []
        self.notes = list(name_notes)
        if not topics_known(endpoints):
            self.notes.append('topics not given for every endpoint (--publish/--subscribe '
                              'TOPIC:TYPE): topic names not checked, one endpoint counted per '
                              'type')
        for requirement in requirements(endpoints):
            if requirement.needed is None:  # templates.hpp's static_assert counts it
                continue
            setting = self._setting(requirement.setting)
            if setting.value < requirement.needed:
                self.misfits.append(misfit_line(setting, requirement.subject, requirement.what,
                                                requirement.needed))
        self._check_receive_limit(messages(endpoints, SUBSCRIBE), receive_limit)
        self._check_publishers(count(endpoints, PUBLISH), publisher_writer)

    def _setting(self, name):
        if name not in self.settings:
            raise GenmrosError('the board settings given define no %s (give the rtps/config.h '
                               'the firmware compiles with)' % name)
        return self.settings[name]

    def _check_receive_limit(self, subscribed, limit):
        if limit is None:
            if subscribed:
                self.notes.append('no receive limit given (--receive-limit): the largest '
                                  'samples not checked')
            return
        if limit.value < DISCOVERY_ANNOUNCEMENT:
            self.warnings.append(
                "%s: %s %d is below %d bytes, a ROS 2 node's SPDP announcement as Fast DDS 3 "
                'sends it (measured; it grows with the host and user names): the board '
                'discovers no such node' % (limit.where(), limit.name, limit.value,
                                            DISCOVERY_ANNOUNCEMENT))
        for message in subscribed:
            datagram = largest_datagram(message)
            if datagram is None:
                self.warnings.append(
                    '%s: %s: a sample has no largest size (unbounded): one larger than %s %d '
                    'does not arrive; bounded storage gives the exact need'
                    % (limit.where(), message.full_name, limit.name, limit.value))
            elif datagram > limit.value:
                self.misfits.append(misfit_line(
                    limit, message.full_name, 'a sample of up to %d bytes in one datagram, RTPS '
                    'around it' % message.max_size, datagram))

    def _check_publishers(self, count, publisher_writer):
        if count < 2:
            return
        if publisher_writer is None:
            self.notes.append('%d publishers: whether this mros2 gives each its own writer is '
                              'not known here (--mros2-root)' % count)
        elif not publisher_writer.has_writer:
            self.misfits.append(
                "%s:%d: the firmware: its %d publishers need a Publisher with a writer of its "
                "own; this mros2 sends every message through the last one created "
                "(mros2::pub_ptr): apply genmros' mros2 patch set (genmros mros2-harden)"
                % (publisher_writer.path, publisher_writer.line, count))

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
