"""The C++ type model: what the templates need to know about a message.

Built from genmsg specs (see :mod:`colcon_mros.parse`); knows C++ spelling,
the ROS 1 wire sizes and the type identity (MD5 sum, definition text, type
ID), and nothing about how headers are laid out, which is the templates' job.
"""

import functools
import math
import os
import zlib

from genmsg.msgs import is_valid_msg_field_name, parse_type

from colcon_mros.errors import GenmrosError
from colcon_mros.floats import FLOAT32_SMALLEST_NORMAL, round_to_type
from colcon_mros.names import member_identifier
from colcon_mros.storage import HeapStorage

SUPPORT_HEADER = 'mros_message_support.h'

# .msg built-in type -> (C++ type, bytes on the wire; None when variable).
BUILTIN_TYPES = {
    'bool': ('uint8_t', 1),
    'int8': ('int8_t', 1),
    'uint8': ('uint8_t', 1),
    'byte': ('int8_t', 1),
    'char': ('uint8_t', 1),
    'int16': ('int16_t', 2),
    'uint16': ('uint16_t', 2),
    'int32': ('int32_t', 4),
    'uint32': ('uint32_t', 4),
    'int64': ('int64_t', 8),
    'uint64': ('uint64_t', 8),
    'float32': ('float', 4),
    'float64': ('double', 8),
    'string': ('std::string', None),
    'time': ('mros::Time', 8),
    'duration': ('mros::Duration', 8),
}

# Header guards of message headers start with this; a header includes those
# of the types it contains and checks their guards.
MESSAGE_GUARD_PREFIX = 'MROS_MSG'

STRING_MIN_SIZE = 4
# The int32_t results of serialize() and deserialize() bound every message.
MAX_MESSAGE_SIZE = (1 << 31) - 1
ARRAY_COUNT_SIZE = 4

# Type IDs live in [FIRST_TYPE_ID, 2**31): clear of the small hand-numbered
# IDs of the earlier mROS headers, and positive in a 32-bit int.
FIRST_TYPE_ID = 1 << 16


def cpp_identifier(name, type_name=None):
    """The C++ spelling of a ROS field or constant name."""
    return member_identifier(name, type_name)


def type_id(full_name):
    """A deterministic type ID derived from the full type name alone."""
    span = (1 << 31) - FIRST_TYPE_ID
    return FIRST_TYPE_ID + zlib.crc32(full_name.encode('utf-8')) % span


def origin(package, path):
    """Where a definition comes from, as pkg/msg/Type.msg: stable across machines."""
    return '/'.join([package, os.path.basename(os.path.dirname(path)), os.path.basename(path)])


def gencpp_definition_text(full_text):
    """The definition text as gencpp (and so roscpp's TCPROS handshake) gives it:
    genmsg's full text with every line, the last included, ending in '\\n'."""
    return ''.join(line + '\n' for line in full_text.splitlines() or [''])


def cpp_string_literal_lines(text):
    """text as C++ string literal pieces, one per line of text.

    Non-ASCII bytes become octal escapes (never followed by a digit that
    could extend them, unlike hex escapes), and '?' after '?' is escaped so
    no trigraph can form.
    """
    pieces = []
    for line in text.splitlines(True):
        out = []
        previous = ''
        for byte in line.encode('utf-8'):
            char = chr(byte)
            if char == '\\' or char == '"':
                out.append('\\' + char)
            elif char == '\n':
                out.append('\\n')
            elif char == '\t':
                out.append('\\t')
            elif char == '?' and previous == '?':
                out.append('\\?')
            elif 32 <= byte < 127:
                out.append(char)
            else:
                out.append('\\%03o' % byte)
            previous = char
        pieces.append('"%s"' % ''.join(out))
    return pieces or ['""']


def _cpp_integer_literal(cpp_type, value):
    """value as a C++98 constant expression of cpp_type.

    C++98 has no long long literals (and -pedantic warns about them), so a
    64-bit value beyond 32 bits is built from two 32-bit halves. No literal
    exceeds its type: the minimum of a signed type is written as -MAX - 1.
    """
    unsigned = cpp_type.startswith('u')
    if cpp_type.endswith('64_t'):
        magnitude = abs(value)
        if magnitude < (1 << 31):
            body = 'static_cast<%s>(%d%s)' % (cpp_type, magnitude, 'u' if unsigned else '')
        elif value == -(1 << 63):
            return '(-%s - 1)' % _cpp_integer_literal(cpp_type, (1 << 63) - 1)
        else:
            body = '(static_cast<uint64_t>(0x%08xu) << 32 | 0x%08xu)' % (
                magnitude >> 32, magnitude & 0xffffffff)
            if not unsigned:
                body = 'static_cast<int64_t>%s' % body
        return '(-%s)' % body if value < 0 else body
    if cpp_type == 'int32_t' and value == -(1 << 31):
        return '(-2147483647 - 1)'
    return '%du' % value if unsigned else '%d' % value


def cpp_constant_literal(ros_type, value):
    """A C++98 expression for a constant of ros_type holding value."""
    if ros_type == 'string':
        return ' '.join(cpp_string_literal_lines(value))
    if ros_type == 'bool':
        return '1' if value else '0'
    if ros_type in ('float32', 'float64'):
        cpp_type = BUILTIN_TYPES[ros_type][0]
        if math.isnan(value):
            return 'std::numeric_limits<%s>::quiet_NaN()' % cpp_type
        if math.isinf(value):
            sign = '-' if value < 0 else ''
            return '%sstd::numeric_limits<%s>::infinity()' % (sign, cpp_type)
        held = round_to_type(ros_type, value)
        # A literal that rounds to zero or to a subnormal float draws a
        # warning from C++ compilers: such a constant is written as the value
        # the float holds, exactly. Other literals keep the definition's digits.
        if cpp_type == 'float' and abs(held) < FLOAT32_SMALLEST_NORMAL:
            value = held
        text = repr(float(value))
        text = text if ('.' in text or 'e' in text) else text + '.0'
        return text + 'f' if cpp_type == 'float' else text
    return _cpp_integer_literal(BUILTIN_TYPES[ros_type][0], value)


class Constant:
    """A constant of a message: a static member of its C++ type.

    Integers are initialized in the class, so they are constant expressions
    (array bounds, case labels); floating-point values are defined outside it,
    as C++98 requires; a string is a char array, which costs no constructor
    at start-up and no heap.
    """

    def __init__(self, genmsg_constant, line):
        self.name = genmsg_constant.name
        self.ros_type = genmsg_constant.type
        self.cpp_name = cpp_identifier(self.name)
        self.is_string = self.ros_type == 'string'
        self.is_integer = not self.is_string and self.ros_type not in ('float32', 'float64')
        self.cpp_type = 'char' if self.is_string else BUILTIN_TYPES[self.ros_type][0]
        self.cpp_literal = cpp_constant_literal(self.ros_type, genmsg_constant.val)
        self.line = line


class ElementType:
    """What a field's element type is in C++ and on the wire."""

    def __init__(self, cpp_type, min_size, max_size, unbounded_reason=None):
        self.cpp_type = cpp_type
        self.min_size = min_size
        self.max_size = max_size  # None: no maximum
        self.unbounded_reason = unbounded_reason


def _array_max_size(element, count, counted):
    if element.max_size is None:
        return None
    return (ARRAY_COUNT_SIZE if counted else 0) + element.max_size * count


class Field:
    """A field of a message: its C++ declaration and its size on the wire."""

    def __init__(self, name, ros_type, element, bounds, line):
        self.name = name
        self.ros_type = ros_type
        self.cpp_name = cpp_identifier(name)
        self.line = line
        base_type, is_array, array_length = parse_type(ros_type)
        self.element_type = base_type
        if not is_array:
            self.cpp_type = element.cpp_type
            self.min_size = element.min_size
            self.max_size = element.max_size
        elif array_length is not None:
            self.cpp_type = 'mros::array<%s, %d>' % (element.cpp_type, array_length)
            self.min_size = element.min_size * array_length
            self.max_size = _array_max_size(element, array_length, counted=False)
        elif bounds.max_count is not None:
            self.cpp_type = 'mros::bounded_vector<%s, %d>' % (element.cpp_type, bounds.max_count)
            self.min_size = ARRAY_COUNT_SIZE
            self.max_size = _array_max_size(element, bounds.max_count, counted=True)
        else:
            self.cpp_type = 'std::vector<%s>' % element.cpp_type
            self.min_size = ARRAY_COUNT_SIZE
            self.max_size = None
        # Where the size has no maximum, as a path to the field that has none:
        # 'header.frame_id (string)'.
        self.unbounded_reason = None
        if self.max_size is None and element.unbounded_reason is not None and (
                not is_array or array_length is not None):
            self.unbounded_reason = '%s%s.%s' % (name, '[]' if is_array else '', element.unbounded_reason)
        elif self.max_size is None:
            self.unbounded_reason = '%s (%s)' % (name, ros_type)


class NamedType:
    """The names a ROS type pkg/Name has in C++."""

    def __init__(self, full_name, guard_prefix):
        self.full_name = full_name
        self.package, self.name = full_name.split('/', 1)
        self.cpp_name = '%s::%s' % (self.package, self.name)
        self.header = '%s.h' % full_name
        # The package's length keeps a_b/C and a/b_C apart; the case is kept.
        self.header_guard = '%s_%d_%s_%s_H' % (guard_prefix, len(self.package), self.package,
                                               self.name)


class Message(NamedType):
    """One message type (or one half of a service) ready for rendering."""

    def __init__(self, full_name, spec, identities, declarations, element_of, storage,
                 definition_text='full'):
        super().__init__(full_name, MESSAGE_GUARD_PREFIX)
        self.source = declarations.path
        self.origin = origin(self.package, self.source)
        self._identities = identities
        self.compact_definition = definition_text == 'compact'
        self.type_id = type_id(full_name)
        self.constants = [Constant(constant, line) for constant, line
                          in zip(spec.constants, declarations.constant_lines)]
        self.fields = []
        for name, ros_type, line in zip(spec.names, spec.types, declarations.field_lines):
            bounds = storage.field_bounds(full_name, name, ros_type, self.source, line)
            self.fields.append(Field(name, ros_type, element_of(ros_type, bounds), bounds, line))
        self.dependencies = sorted({f.element_type for f in self.fields if '/' in f.element_type})
        self.includes = [NamedType(dependency, MESSAGE_GUARD_PREFIX) for dependency in self.dependencies]
        self.min_size = sum(f.min_size for f in self.fields)
        unbounded = [f for f in self.fields if f.max_size is None]
        # The largest wire image, where one exists: fixed-size types, and every
        # type in bounded storage.
        self.max_size = None if unbounded else sum(f.max_size for f in self.fields)
        self.is_fixed_size = self.max_size == self.min_size
        self.unbounded_reason = unbounded[0].unbounded_reason if unbounded else None
        for member in self.fields + self.constants:
            member.cpp_name = cpp_identifier(member.name, self.name)
        if self.min_size > MAX_MESSAGE_SIZE:
            raise GenmrosError('%s takes at least %d bytes on the wire, more than the %d a message '
                               'can have' % (full_name, self.min_size, MAX_MESSAGE_SIZE), self.source)
        if self.max_size is not None and self.max_size > MAX_MESSAGE_SIZE:
            raise GenmrosError('%s can take %d bytes on the wire, more than the %d a message can '
                               'have' % (full_name, self.max_size, MAX_MESSAGE_SIZE), self.source)
        self._check_names()

    # The identity is computed when a template asks for it: a header needs
    # only its own, while the model is built for every type it contains.
    @functools.cached_property
    def md5sum(self):
        return self._identities.md5_of(self.full_name)

    @functools.cached_property
    def definition(self):
        return gencpp_definition_text(
            self._identities.full_text(self.full_name, self.compact_definition))

    @functools.cached_property
    def definition_lines(self):
        return cpp_string_literal_lines(self.definition)

    def _check_names(self):
        # genmsg checks field names but takes any text before '=' as a constant's name.
        for constant in self.constants:
            if not is_valid_msg_field_name(constant.name):
                raise GenmrosError("'%s' is not a legal constant name" % constant.name,
                                   self.source, constant.line)
        seen = {}
        for member in sorted(self.fields + self.constants, key=lambda m: m.line):
            if member.cpp_name in seen:
                raise GenmrosError(
                    "name '%s' is already declared on line %d" % (member.name, seen[member.cpp_name]),
                    self.source, member.line)
            seen[member.cpp_name] = member.line


class Service(NamedType):
    """A service: its request and response messages and the service's own identity."""

    def __init__(self, full_name, spec, identities, request, response):
        super().__init__(full_name, 'MROS_SRV')
        self.source = request.source
        self.origin = request.origin
        self.md5sum = identities.service_md5(spec)
        self.request = request
        self.response = response
        self.dependencies = request.dependencies + response.dependencies


class ModelBuilder:
    """Turns specs loaded by a :class:`colcon_mros.parse.SpecLoader` into models."""

    def __init__(self, loader, storage=None, definition_text='full'):
        self.loader = loader
        self.storage = storage or HeapStorage()
        self.definition_text = definition_text
        self._messages = {}

    def message(self, full_name):
        """The model of a loaded message type, built once."""
        if full_name not in self._messages:
            spec = self.loader.context.get_registered(full_name)
            self._messages[full_name] = Message(
                full_name, spec, self.loader.identities,
                self.loader.declarations(full_name), self._element, self.storage,
                self.definition_text)
        return self._messages[full_name]

    def service(self, spec):
        return Service(spec.full_name, spec, self.loader.identities,
                       self.message(spec.request.full_name),
                       self.message(spec.response.full_name))

    def closure(self, full_names):
        """The messages named and every message they contain, dependencies first."""
        ordered = []
        visiting = set()

        def visit(full_name):
            if full_name in visiting:
                return
            visiting.add(full_name)
            message = self.message(full_name)
            for dependency in message.dependencies:
                visit(dependency)
            ordered.append(message)

        for full_name in full_names:
            visit(full_name)
        return ordered

    def _element(self, ros_type, bounds):
        """The :class:`ElementType` of a field's type, arrays aside."""
        base_type = parse_type(ros_type)[0]
        if base_type == 'string':
            if bounds.max_size is None:
                return ElementType('std::string', STRING_MIN_SIZE, None, None)
            return ElementType('mros::bounded_string<%d>' % bounds.max_size, STRING_MIN_SIZE,
                               STRING_MIN_SIZE + bounds.max_size)
        if base_type in BUILTIN_TYPES:
            cpp_type, size = BUILTIN_TYPES[base_type]
            return ElementType(cpp_type, size, size)
        nested = self.message(base_type)
        return ElementType(nested.cpp_name, nested.min_size, nested.max_size, nested.unbounded_reason)


def _bytes(count):
    return '%d byte%s' % (count, '' if count == 1 else 's')


class MaxSizeEntry:
    """The publish buffer one message type needs."""

    def __init__(self, message, variable_budget):
        self.full_name = message.full_name
        if message.max_size is None:
            self.size = max(variable_budget, message.min_size)
            self.description = 'no maximum, %s has no bound; counted as %s' % (
                message.unbounded_reason, _bytes(self.size))
        elif message.is_fixed_size:
            self.size = message.max_size
            self.description = 'exactly %s' % _bytes(message.max_size)
        else:
            self.size = message.max_size
            self.description = 'at most %s' % _bytes(message.max_size)


class MaxSize:
    """PUB_MSG_MAX_SIZE for a firmware's message types."""

    def __init__(self, messages, variable_budget):
        self.variable_budget = variable_budget
        self.entries = [MaxSizeEntry(message, variable_budget) for message in messages]
        self.max_size = max([entry.size for entry in self.entries] or [0])
        self.has_unbounded = any(message.max_size is None for message in messages)
