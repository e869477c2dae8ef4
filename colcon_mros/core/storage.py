# SPDX-License-Identifier: BSD-3-Clause
"""How strings and variable arrays are stored: on the heap, or bounded.

Heap storage (the default, and the only one catkin builds write) gives
``std::string`` and ``std::vector``, as roscpp does. Bounded storage, chosen
per firmware (``genmros mros-v1-export --storage bounded``), holds every string and
variable array inside the message with a maximum length, so a firmware
needs no heap; the maxima come from options files in the spirit of nanopb's
``.options``::

    # <pkg>/msg/genmros.options, read for that package's types
    PersonalData.first_name  max_size:32
    PersonalData.last_name   max_size:32

    # a firmware's own file (genmros mros-v1-export --options FILE): full type names,
    # and '*' for every field that has no bound of its own
    sensor_msgs/JointState.name  max_count:6 max_size:16
    *                            max_size:64 max_count:16

``max_size`` bounds a string (in bytes; for ``string[]``, each element),
``max_count`` the elements of a variable array. A firmware's file wins over
a package's; a field's own line wins over ``*``.
"""

import os
import re

from colcon_mros.errors import GenmrosError

PACKAGE_OPTIONS_FILE = 'genmros.options'
OPTION_KEYS = ('max_size', 'max_count')
ANY_FIELD = '*'

_TARGET = re.compile(
    r'^(?:(?P<package>[A-Za-z][\w]*)/)?(?P<type>[A-Za-z]\w*)\.(?P<field>[A-Za-z]\w*)$')


class FieldShape:
    """What storage needs to know of a field, from any front end: its type
    as the definition spells it, and whether it is a string (or has string
    elements) and a variable array without a bound of its own."""

    def __init__(self, type_text, is_string, is_variable_array):
        self.type_text = type_text
        self.is_string = is_string
        self.is_variable_array = is_variable_array


class FieldBounds:
    """The maxima of one field: string bytes and array elements (None: no bound)."""

    def __init__(self, max_size=None, max_count=None):
        self.max_size = max_size
        self.max_count = max_count


class _Entry:
    """One line of an options file: which field, which bounds, where written."""

    def __init__(self, full_type, field, bounds, path, line):
        self.full_type = full_type
        self.field = field
        self.bounds = bounds
        self.path = path
        self.line = line


def _parse_bound(text, path, line):
    key, separator, value = text.partition(':')
    if not separator or key not in OPTION_KEYS:
        raise GenmrosError("unknown option '%s' (expected max_size:N or max_count:N)" % text,
                           path, line)
    if not value.isdigit() or int(value) <= 0:
        raise GenmrosError("%s must be a positive integer, not '%s'" % (key, value), path, line)
    return key, int(value)


def read_options_file(path, package=None):
    """The entries of one options file; package qualifies bare type names
    (a package's own file), or None when full names are required."""
    try:
        with open(path, encoding='utf-8') as stream:
            lines = stream.read().split('\n')
    except (OSError, UnicodeDecodeError) as error:
        raise GenmrosError('cannot read options file: %s'
                           % (getattr(error, 'strerror', None) or error), path)
    entries = []
    for number, text in enumerate(lines, 1):
        words = text.split('#')[0].split()
        if not words:
            continue
        target, options = words[0], words[1:]
        if not options:
            raise GenmrosError("'%s' sets no bound (expected max_size:N or max_count:N)" % target,
                               path, number)
        bounds = FieldBounds()
        for option in options:
            key, value = _parse_bound(option, path, number)
            setattr(bounds, key, value)
        if target == ANY_FIELD:
            entries.append(_Entry(None, None, bounds, path, number))
            continue
        match = _TARGET.match(target)
        if not match or (match.group('package') or package) is None:
            raise GenmrosError("'%s' names no field (expected %sType.field or '*')"
                               % (target, '' if package else 'package/'), path, number)
        full_type = '%s/%s' % (match.group('package') or package, match.group('type'))
        entries.append(_Entry(full_type, match.group('field'), bounds, path, number))
    return entries


class HeapStorage:
    """std::string and std::vector: no bounds, the heap holds what arrives."""

    bounded = False
    option_files = ()

    def field_bounds(self, message_name, field_name, shape, path, line):
        return FieldBounds()

    def check(self, field_shape):
        pass


class BoundedStorage:
    """Strings and variable arrays inside the message, with the maxima of
    the options files; a field that needs a bound and has none is an error."""

    bounded = True

    def __init__(self, firmware_option_files=(), package_option_files=()):
        # Later entries win: package files first, then the firmware's.
        self.option_files = [path for _, path in package_option_files] + \
            list(firmware_option_files)
        self._entries = []
        for package, path in package_option_files:
            self._entries.extend(read_options_file(path, package))
        for path in firmware_option_files:
            self._entries.extend(read_options_file(path))
        self._fields = {}
        self._default = FieldBounds()
        for entry in self._entries:
            target = self._default if entry.full_type is None else self._fields.setdefault(
                (entry.full_type, entry.field), FieldBounds())
            for key in OPTION_KEYS:
                if getattr(entry.bounds, key) is not None:
                    setattr(target, key, getattr(entry.bounds, key))

    def field_bounds(self, message_name, field_name, shape, path, line):
        """The FieldBounds of a field of message_name with a FieldShape."""
        own = self._fields.get((message_name, field_name), FieldBounds())
        bounds = FieldBounds(
            own.max_size if own.max_size is not None else self._default.max_size,
            own.max_count if own.max_count is not None else self._default.max_count)
        for key, needed in (('max_size', shape.is_string),
                            ('max_count', shape.is_variable_array)):
            if needed and getattr(bounds, key) is None:
                raise GenmrosError(
                    "field '%s' (%s) has no %s for bounded storage (add '%s.%s %s:N' to an "
                    'options file)' % (field_name, shape.type_text, key, message_name,
                                       field_name, key),
                    path, line)
        return bounds

    def check(self, field_shape):
        """Every field an options file names exists and can take its bounds.
        field_shape(full_type, field) gives a FieldShape, None for a type
        without that field, and raises GenmrosError for an unknown type."""
        for entry in self._entries:
            if entry.full_type is None:
                continue
            try:
                shape = field_shape(entry.full_type, entry.field)
            except GenmrosError:
                raise GenmrosError("unknown type '%s'" % entry.full_type, entry.path, entry.line)
            if shape is None:
                raise GenmrosError("type '%s' has no field '%s'" % (entry.full_type, entry.field),
                                   entry.path, entry.line)
            if entry.bounds.max_size is not None and not shape.is_string:
                raise GenmrosError("max_size bounds strings; '%s.%s' is %s"
                                   % (entry.full_type, entry.field, shape.type_text),
                                   entry.path, entry.line)
            if entry.bounds.max_count is not None and not shape.is_variable_array:
                raise GenmrosError("max_count bounds variable arrays; '%s.%s' is %s"
                                   % (entry.full_type, entry.field, shape.type_text),
                                   entry.path, entry.line)


def package_option_files(msg_dirs_by_package):
    """(package, path) of every genmros.options beside a package's .msg files."""
    found = []
    for package in sorted(msg_dirs_by_package):
        for directory in msg_dirs_by_package[package]:
            path = os.path.join(directory, PACKAGE_OPTIONS_FILE)
            if os.path.isfile(path):
                found.append((package, path))
    return found


def storage_for(kind, firmware_option_files, msg_dirs_by_package):
    """The storage a run uses: heap, or bounded by the options files."""
    if kind == 'heap':
        if firmware_option_files:
            raise GenmrosError('--options sets bounds, which only --storage bounded uses')
        return HeapStorage()
    return BoundedStorage(firmware_option_files, package_option_files(msg_dirs_by_package))
