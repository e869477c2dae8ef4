"""A library's settings, read from its configuration headers, and the one
line a fit check writes for a setting too small.

The settings are ``#define``s of numbers (mROS v1's ``mros_usr_config.h``
and ``mros_packet_config.h``), read as the preprocessor reads a number,
with the file and line that set each. A back end's fit check names which
settings a type needs; :func:`misfit_line` is the line every fit check
writes for one that is too small, so the build's lines read alike for every
library.
"""

import re

from colcon_mros.errors import GenmrosError

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
            raise GenmrosError('cannot read the library settings: %s' % error.strerror, path)
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


def misfit_line(setting, subject, what, needed, note=''):
    """FILE:LINE of setting, then the subject (a type), what needs the
    setting, the value it needs and the value it has (and a note)."""
    return ('%s: %s: %s needs %s >= %d (it is %d%s)'
            % (setting.where(), subject, what, setting.name, needed, setting.value, note))
