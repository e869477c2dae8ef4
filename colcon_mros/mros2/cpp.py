# SPDX-License-Identifier: BSD-3-Clause
"""The C++ view of the ROS 2 type model: what the mros2 templates read.

Names as rosidl gives them (``pkg/msg/type_name.hpp`` declares
``pkg::msg::TypeName``, DDS type name ``pkg::msg::dds_::TypeName_``),
member types a ROS 2 C++ user expects (``std::string``, ``std::u16string``,
``std::array``, ``std::vector``), ``mros::bounded_string`` and
``mros::bounded_vector`` where a bound is known (``string<=N``, ``T[<=N]``,
and bounded storage), and default values and constants as C++11 literals.
"""

import ast
import os

from colcon_mros.core.cpp_literals import (comment_lines, cpp_number_literal,
                                           cpp_string_literal_lines)
from colcon_mros.core.cpp_names import CPP_KEYWORDS
from colcon_mros.ros2.rosidl import type_file_stem

# rosidl's number types -> C++ (rosidl_generator_cpp's, with octet and char as uint8_t).
NUMBER_TYPES = {
    'boolean': 'bool', 'octet': 'uint8_t', 'char': 'uint8_t', 'int8': 'int8_t',
    'uint8': 'uint8_t', 'int16': 'int16_t', 'uint16': 'uint16_t', 'int32': 'int32_t',
    'uint32': 'uint32_t', 'int64': 'int64_t', 'uint64': 'uint64_t', 'float': 'float',
    'double': 'double',
}
WIRE_HEADER = 'mros2_message_wire.hpp'
WIRE_VERSION = 1
# The static headers an mros2 export holds besides the messages.
SUPPORT_HEADERS = (WIRE_HEADER, 'mros_message_containers.h')


def identifier(name):
    """A member or constant name as C++ takes it: rosidl's names are
    lowercase or uppercase words, so only keywords need a trailing '_'."""
    return name + '_' if name in CPP_KEYWORDS else name


def _number_literal(number_type, value):
    if number_type == 'boolean':
        return 'true' if value else 'false'
    return cpp_number_literal(NUMBER_TYPES[number_type], value)


def _wstring_literal(text):
    """A u"" literal of text; characters beyond ASCII as \\u escapes."""
    pieces = []
    for char in text:
        if char in '\\"':
            pieces.append('\\' + char)
        elif 32 <= ord(char) < 127:
            pieces.append(char)
        elif ord(char) <= 0xffff:
            pieces.append('\\u%04x' % ord(char))
        else:
            pieces.append('\\U%08x' % ord(char))
    return 'u"%s"' % ''.join(pieces)


class CppMember:
    """A member as a class member: its C++ type, name and initializer."""

    def __init__(self, member):
        self.name = identifier(member.name)
        self.comment = comment_lines(member.comment)
        self.type = self._container_type(member, self._element_type(member))
        self.initializer = self._initializer(member)

    @staticmethod
    def _element_type(member):
        if member.element == 'number':
            return NUMBER_TYPES[member.number_type]
        if member.element == 'message':
            return CppMessageName(member.message).cpp_name
        if member.element == 'wstring':
            return 'std::u16string'
        if member.string_bound is not None:
            return 'mros::bounded_string<%d>' % member.string_bound
        return 'std::string'

    @staticmethod
    def _container_type(member, element):
        if member.container == 'array':
            return 'std::array<%s, %d>' % (element, member.count)
        if member.is_sequence and member.count is not None:
            return 'mros::bounded_vector<%s, %d>' % (element, member.count)
        if member.is_sequence:
            return 'std::vector<%s>' % element
        return element

    def _element_literal(self, member, value):
        if member.element == 'number':
            return _number_literal(member.number_type, value)
        if member.element == 'wstring':
            return _wstring_literal(value)
        return ' '.join(cpp_string_literal_lines(value))

    def _initializer(self, member):
        """' = value' / '{{...}}' for a default; numbers without one start at 0."""
        if member.default is None:
            if member.element == 'number' and member.container is None:
                return ' = %s' % _number_literal(member.number_type, 0)
            if member.element == 'number' and member.container == 'array':
                return '{}'
            return ''
        if member.container is None:
            return ' = %s' % self._element_literal(member, member.default)
        values = member.default
        if isinstance(values, str):
            values = ast.literal_eval(values)
        literals = ', '.join(self._element_literal(member, value) for value in values)
        return '{{%s}}' % literals if member.container == 'array' else '{%s}' % literals


class CppConstant:
    def __init__(self, constant):
        self.name = identifier(constant.name)
        if constant.is_string:
            self.type = 'const char*'
            self.literal = ' '.join(cpp_string_literal_lines(constant.value))
        else:
            self.type = NUMBER_TYPES[constant.number_type]
            self.literal = _number_literal(constant.number_type, constant.value)


def _source(model):
    """The definition a header comes from: 'pkg/msg/Type.msg'."""
    return '%s/%s/%s' % (model.package, os.path.basename(os.path.dirname(model.source)),
                         os.path.basename(model.source))


class CppMessageName:
    """The names a message type has in C++ and on the wire, and its header's."""

    def __init__(self, message):
        self.package = message.package
        self.kind = message.kind
        self.name = message.name
        self.cpp_name = '%s::%s::%s' % (message.package, message.kind, message.name)
        self.dds_type_name = '%s::%s::dds_::%s_' % (message.package, message.kind, message.name)
        # What embeddedRTPS' type name field needs: the name and its terminating NUL.
        self.dds_type_name_size = len(self.dds_type_name) + 1
        # A service's halves live in the service's header.
        self.header = header_path(message.package, message.kind,
                                  message.name.rpartition('_')[0] if message.kind == 'srv'
                                  else message.name)


class CppMessage(CppMessageName):
    """A message as the mros2 template reads it."""

    def __init__(self, message):
        super().__init__(message)
        self.comment = comment_lines(message.comment)
        self.source = _source(message)
        self.summary = 'mros2 message %s, DDS type %s.' % (self.cpp_name, self.dds_type_name)
        self.members = [CppMember(member) for member in message.members]
        self.constants = [CppConstant(constant) for constant in message.constants]
        self.includes = sorted({CppMessageName(d).header for d in message.dependencies
                                if CppMessageName(d).header != self.header})
        self.guard = header_guard(self.header)


class CppService:
    """A service: its header holds both halves."""

    def __init__(self, service):
        self.package = service.package
        self.kind = 'srv'
        self.name = service.name
        self.cpp_name = '%s::srv::%s' % (service.package, service.name)
        self.header = header_path(service.package, 'srv', service.name)
        self.guard = header_guard(self.header)
        self.source = _source(service)
        self.request = CppMessage(service.request)
        self.response = CppMessage(service.response)
        self.summary = 'mros2 service %s: %s and %s.' % (self.cpp_name, self.request.cpp_name,
                                                         self.response.cpp_name)
        self.includes = sorted(set(self.request.includes + self.response.includes))


def header_path(package, kind, name):
    """The header of a message or service below an include root, by rosidl's
    name rule: ('pkg', 'msg', 'TypeName') -> 'pkg/msg/type_name.hpp'."""
    return '%s/%s/%s.hpp' % (package, kind, type_file_stem(name))


def header_guard(header):
    """rosidl's guard style, apart from rosidl's own C++ headers:
    'pkg/msg/type_name.hpp' -> 'MROS2__PKG__MSG__TYPE_NAME_HPP_'."""
    return 'MROS2__' + header.upper().replace('/', '__').replace('.', '_') + '_'
