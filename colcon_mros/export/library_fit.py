"""The fit check: a firmware's types against its mROS v1 library's settings.

The settings are ``#define``s in the library's and the app's configuration
headers (``mros_packet_config.h`` of the library, ``mros_usr_config.h`` of
the app's mros_config/ or the library's default); what the types need is
:mod:`colcon_mros.generator.library_needs`. Each setting that is too small
for a type is a :class:`Misfit`: one line naming the type, the setting, the
file and line that set it, its value and the value needed. A type without a
largest frame (a string or variable array in heap storage) only might not
fit a memory pool: that is a warning, with bounded storage as the way to an
exact answer.
"""

import re

from colcon_mros.errors import GenmrosError, GenmrosProblems
from colcon_mros.generator.library_needs import (PEER_NAME_MAX, POOL_KINDS, REPLY_BUFFER,
                                                 REQUEST_BUFFER, SHORTEST_NAMES, TABLES,
                                                 TOPIC_NAME_MAX, TYPENAME_MAX)

_DEFINE = re.compile(r'^\s*#\s*define\s+([A-Za-z_]\w*)\s+(.*?)\s*(?://.*|/\*.*)?$')
_NUMBER = re.compile(r'^\(?\s*(\d+)[uUlL]*\s*\)?$')
_REFERENCE = re.compile(r'^\(?\s*([A-Za-z_]\w*)\s*\)?$')


class Setting:
    """One #define: its name, value, and where it is."""

    def __init__(self, name, value, path, line):
        self.name = name
        self.value = value
        self.path = path
        self.line = line

    def where(self):
        return '%s:%d' % (self.path, self.line)


def read_settings(paths):
    """{name: Setting} of the numeric #defines in paths (a later file's
    define of a name does not replace an earlier one's: list the file the
    build includes first first). A define naming another is followed."""
    raw = {}
    for path in paths:
        try:
            with open(path, encoding='utf-8', errors='replace') as stream:
                lines = stream.read().splitlines()
        except OSError as error:
            raise GenmrosError('cannot read the mROS v1 settings: %s' % error.strerror, path)
        for number, line in enumerate(lines, 1):
            match = _DEFINE.match(line)
            if match and match.group(1) not in raw:
                raw[match.group(1)] = (match.group(2), path, number)
    settings = {}
    for name, (text, path, line) in raw.items():
        seen = {name}
        while _REFERENCE.match(text) and _REFERENCE.match(text).group(1) in raw:
            reference = _REFERENCE.match(text).group(1)
            if reference in seen:
                break
            seen.add(reference)
            text = raw[reference][0]
        number = _NUMBER.match(text)
        if number:
            settings[name] = Setting(name, int(number.group(1)), path, line)
    return settings


class Misfit:
    """A setting too small for a type: the build's one line. A connection
    header's needed value counts with the longest names; certain, what it
    needs even with the shortest."""

    def __init__(self, type_name, what, setting, needed, certain=None):
        self.type_name = type_name
        self.what = what
        self.setting = setting
        self.needed = needed
        self.certain = certain

    def line(self):
        """FILE:LINE of the setting, then the type, what needs it, the value
        it needs and the value it has."""
        shortest = ('' if self.certain is None
                    else '; even with the shortest topic and caller id it needs %d' % self.certain)
        return ('%s: %s: %s needs %s >= %d (it is %d%s)'
                % (self.setting.where(), self.type_name, self.what, self.setting.name,
                   self.needed, self.setting.value, shortest))


def _required(settings, name):
    if name not in settings:
        raise GenmrosError('the mROS v1 settings given define no %s (give the library\'s '
                           'mros_packet_config.h and the app\'s mros_usr_config.h)' % name)
    return settings[name]


def largest_pool(settings, kind):
    """The Setting of the largest memory pool block of one PoolKind."""
    count = _required(settings, kind.count).value
    pools = [settings[name] for name in kind.sizes[:count] if name in settings]
    if not pools:
        raise GenmrosError('the mROS v1 settings given define none of %s' % ', '.join(
            kind.sizes[:max(count, 1)]))
    return max(pools, key=lambda pool: pool.value)


class Requirement:
    """What one type needs of one setting: needed bytes for certain (None
    where there is no largest size: a frame in heap storage); a connection
    header also names_free, its bytes besides the names (topic and caller
    id), and assumed, its bytes with the longest names counted with."""

    def __init__(self, what, setting, needed, names_free=None, assumed=None):
        self.what = what
        self.setting = setting
        self.needed = needed
        self.names_free = names_free
        self.assumed = assumed

    @property
    def fits(self):
        return self.needed is not None and self.setting.value >= self.needed

    @property
    def names_budget(self):
        """For a header that fits only with short names: the bytes the topic
        and the peer's caller id may take together; else None."""
        if self.assumed is None or not self.fits or self.setting.value >= self.assumed:
            return None
        return self.setting.value - self.names_free


class Fit:
    """A firmware's types (LibraryNeeds) against settings ({name: Setting}):
    the misfits (errors) and the warnings, and each type's requirements."""

    def __init__(self, needs, settings):
        self.needs = needs
        self.settings = settings
        self.topic_name_max = _required(settings, TOPIC_NAME_MAX)
        self.request_buffer = _required(settings, REQUEST_BUFFER)
        self.reply_buffer = _required(settings, REPLY_BUFFER)
        self.typename_max = _required(settings, TYPENAME_MAX)
        self.pools = [(kind.use, largest_pool(settings, kind)) for kind in POOL_KINDS]
        self.longest_names = self.topic_name_max.value + PEER_NAME_MAX
        self.misfits = []
        self.warnings = []
        for needed in needs.types:
            requirements = self.requirements(needed)
            self.misfits += [Misfit(needed.full_name, r.what, r.setting, r.assumed, r.needed)
                             if r.assumed is not None else
                             Misfit(needed.full_name, r.what, r.setting, r.needed)
                             for r in requirements if r.needed is not None and not r.fits]
            self.warnings += [
                '%s: %s needs %s >= %d; %s sets %d, which holds it only while the topic and the '
                "peer's caller id take at most %d bytes together"
                % (needed.full_name, r.what, r.setting.name, r.assumed, r.setting.where(),
                   r.setting.value, r.names_budget)
                for r in requirements if r.names_budget is not None]
            if needed.pool_block is None:
                self.warnings.append(
                    '%s: no largest frame (%s has no bound): a frame may be larger than the '
                    'largest memory pool block (%s); bounded storage gives the exact need'
                    % (needed.full_name, needed.unbounded_reason,
                       ', '.join('%s: %s = %d at %s' % (use, pool.name, pool.value, pool.where())
                                 for use, pool in self.pools)))

    def requirements(self, needed):
        """The Requirements of one TypeNeeds, one per setting it depends on."""
        requirements = []
        for what, setting, free in (
                ("a ROS subscriber's connection header (definition text %d bytes, a topic of up "
                 'to %d and a caller id of up to %d, and the NUL)'
                 % (needed.text_bytes, self.topic_name_max.value, PEER_NAME_MAX),
                 self.request_buffer, needed.subscriber_header),
                ("a ROS publisher's connection header", self.reply_buffer,
                 needed.publisher_header)):
            requirements.append(Requirement(what, setting, free + SHORTEST_NAMES, free,
                                            free + self.longest_names))
        requirements += [
            Requirement('its name with its NUL', self.typename_max, needed.type_name_size),
            Requirement('its name with its NUL', self.topic_name_max, needed.type_name_size),
        ]
        for use, pool in self.pools:
            requirements.append(Requirement(
                'a frame of up to %s bytes, %s,' % (needed.max_frame, use), pool,
                needed.pool_block))
        return requirements

    def refuse(self, strict=False):
        """Raise the misfits (and with strict, the warnings too) as one error
        line each."""
        problems = [misfit.line() for misfit in self.misfits] + (self.warnings if strict else [])
        if problems:
            raise GenmrosProblems(problems)

    def table_sizes(self):
        """The Settings of the library's tables this firmware's topics take room in."""
        return [self.settings[name] for name in TABLES if name in self.settings]
