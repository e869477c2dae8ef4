# SPDX-License-Identifier: BSD-3-Clause
"""The C++ names of the type model: what the templates read.

Wraps a :class:`colcon_mros.ros1.model.Message` or ``Service`` in a view that
spells it in C++: type and member names (escaped where C++ or the headers
own the name, see :mod:`colcon_mros.mros_v1.names`), field types with the containers
of the storage choice (``std::string``/``std::vector`` without bounds,
``mros::bounded_string``/``mros::bounded_vector`` with them), constant
literals that compile without a warning from gnu++98 to C++17, header paths
and guards. The model stays free of C++; the templates stay free of logic.
"""

from colcon_mros import __version__
from colcon_mros.core.cpp_literals import (comment_lines, cpp_number_literal,
                                           cpp_string_literal_lines)
from colcon_mros.errors import GenmrosError
from colcon_mros.mros_v1.names import member_identifier

# The support header every message header includes, and the headers it
# includes: static ones in support/ (the containers header: the core's),
# and its version, generated.
SUPPORT_HEADER = 'mros_message_support.h'
SUPPORT_VERSION_HEADER = 'mros_message_support_version.h'
SUPPORT_HEADERS = (SUPPORT_HEADER, 'mros_message_containers.h', 'mros_message_wire.h',
                   SUPPORT_VERSION_HEADER)


def _version_number(version):
    """'1.2.3' as 10203: what MROS_MESSAGE_SUPPORT_VERSION holds."""
    major, minor, patch = (int(part) for part in version.split('.')[:3])
    return major * 10000 + minor * 100 + patch


# The support version header defines it; every message header checks it.
SUPPORT_VERSION = _version_number(__version__)
# Header guards of message headers start with this; a header includes those
# of the types it contains and checks their guards.
MESSAGE_GUARD_PREFIX = 'MROS_MSG'
SERVICE_GUARD_PREFIX = 'MROS_SRV'

# .msg built-in type -> C++ type (roscpp's).
BUILTIN_TYPES = {
    'bool': 'uint8_t', 'int8': 'int8_t', 'uint8': 'uint8_t', 'byte': 'int8_t', 'char': 'uint8_t',
    'int16': 'int16_t', 'uint16': 'uint16_t', 'int32': 'int32_t', 'uint32': 'uint32_t',
    'int64': 'int64_t', 'uint64': 'uint64_t', 'float32': 'float', 'float64': 'double',
    'string': 'std::string', 'time': 'mros::Time', 'duration': 'mros::Duration',
}


def cpp_constant_literal(ros_type, value):
    """A C++98 expression for a constant of ros_type holding value."""
    if ros_type == 'string':
        return ' '.join(cpp_string_literal_lines(value))
    if ros_type == 'bool':
        return '1' if value else '0'
    return cpp_number_literal(BUILTIN_TYPES[ros_type], value)


class CppType:
    """The names a ROS type pkg/Name has in C++, and its header's."""

    def __init__(self, full_name, guard_prefix=MESSAGE_GUARD_PREFIX):
        self.full_name = full_name
        self.package, self.name = full_name.split('/', 1)
        self.cpp_name = '%s::%s' % (self.package, self.name)
        self.header = '%s.h' % full_name
        # The package's length keeps a_b/C and a/b_C apart; the case is kept.
        self.header_guard = '%s_%d_%s_%s_H' % (guard_prefix, len(self.package), self.package,
                                               self.name)


def _element_cpp_type(field):
    element = field.element
    if element.message is not None:
        return CppType(element.ros_type).cpp_name
    if element.ros_type == 'string' and field.bounds.max_size is not None:
        return 'mros::bounded_string<%d>' % field.bounds.max_size
    return BUILTIN_TYPES[element.ros_type]


def field_cpp_type(field):
    """The C++ type of a field, with the containers its bounds call for."""
    element = _element_cpp_type(field)
    if field.is_fixed_array:
        return 'mros::array<%s, %d>' % (element, field.array_length)
    if field.is_variable_array and field.bounds.max_count is not None:
        return 'mros::bounded_vector<%s, %d>' % (element, field.bounds.max_count)
    if field.is_variable_array:
        return 'std::vector<%s>' % element
    return element


class CppField:
    """A field as a struct member."""

    def __init__(self, field, cpp_name):
        self.name = field.name
        self.ros_type = field.ros_type
        self.cpp_name = cpp_name
        self.cpp_type = field_cpp_type(field)
        self.line = field.line
        self.comment = comment_lines(field.comment)


class CppConstant:
    """A constant as a static member.

    Integers are initialized in the class, so they are constant expressions
    (array bounds, case labels); floating-point values are defined outside it,
    as C++98 requires; a string is a char array, which costs no constructor
    at start-up and no heap.
    """

    def __init__(self, constant, cpp_name):
        self.name = constant.name
        self.cpp_name = cpp_name
        self.is_string = constant.is_string
        self.is_integer = constant.is_integer
        self.cpp_type = 'char' if constant.is_string else BUILTIN_TYPES[constant.ros_type]
        self.cpp_literal = cpp_constant_literal(constant.ros_type, constant.value)
        self.line = constant.line
        self.comment = comment_lines(constant.comment)


def _check_unique_members(message, members):
    """Two members whose C++ names meet (EOF escaped to EOF_ beside a field
    EOF_) are refused at the later one's line."""
    seen = {}
    for member in sorted(members, key=lambda m: m.line):
        if member.cpp_name in seen:
            raise GenmrosError(
                "name '%s' is already declared on line %d" % (member.name, seen[member.cpp_name]),
                message.source, member.line)
        seen[member.cpp_name] = member.line


class CppMessage(CppType):
    """A message type as its header spells it."""

    def __init__(self, message):
        super().__init__(message.full_name)
        self._message = message
        self.origin = message.definition_file.key
        self.comment = comment_lines(message.comment)
        self.type_id = message.type_id
        self.min_size = message.min_size
        self.max_size = message.max_size
        self.has_max_size = message.max_size is not None
        self.compact_definition = message.compact_definition
        self.includes = [CppType(dependency) for dependency in message.dependencies]
        self.fields = [CppField(f, member_identifier(f.name, self.name)) for f in message.fields]
        self.constants = [CppConstant(c, member_identifier(c.name, self.name))
                          for c in message.constants]
        _check_unique_members(message, self.fields + self.constants)

    @property
    def md5sum(self):
        return self._message.md5sum

    @property
    def definition_lines(self):
        return cpp_string_literal_lines(self._message.definition)


class CppService(CppType):
    """A service as its header spells it."""

    def __init__(self, service):
        super().__init__(service.full_name, SERVICE_GUARD_PREFIX)
        self.origin = service.definition_file.key
        self.md5sum = service.md5sum
        self.request = CppType(service.request.full_name)
        self.response = CppType(service.response.full_name)
        # The service and its halves, whose traits the header specializes alike.
        self.cpp_names = [self.cpp_name, self.request.cpp_name, self.response.cpp_name]
