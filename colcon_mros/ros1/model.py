# SPDX-License-Identifier: BSD-3-Clause
"""The type model: the structure of messages and services.

Built from genmsg specs (see :mod:`colcon_mros.ros1.parse`): fields and constants,
the ROS 1 wire sizes each field and message can take (which the storage
choice bounds), the nested types, and the type identity (MD5 sum,
definition text, type ID). It knows nothing of C++ spelling, which is
:mod:`colcon_mros.mros_v1.cpp`'s job, nor of header layout, which is the templates'.
"""

import functools
import zlib

from genmsg.msgs import is_valid_msg_field_name, parse_type

from colcon_mros.core.closure import contained_first
from colcon_mros.core.defaults import DEFAULT_DEFINITION_TEXT
from colcon_mros.core.storage import FieldShape, HeapStorage
from colcon_mros.errors import GenmrosError
from colcon_mros.ros1.definition import Definition

# .msg built-in type -> bytes on the wire (None: variable).
BUILTIN_SIZES = {
    'bool': 1, 'int8': 1, 'uint8': 1, 'byte': 1, 'char': 1,
    'int16': 2, 'uint16': 2, 'int32': 4, 'uint32': 4, 'int64': 8, 'uint64': 8,
    'float32': 4, 'float64': 8, 'string': None, 'time': 8, 'duration': 8,
}
FLOAT_TYPES = ('float32', 'float64')

STRING_MIN_SIZE = 4
# The int32_t results of serialize() and deserialize() bound every message.
MAX_MESSAGE_SIZE = (1 << 31) - 1
ARRAY_COUNT_SIZE = 4

# Type IDs live in [FIRST_TYPE_ID, 2**31): clear of the small hand-numbered
# IDs of the earlier mROS headers, and positive in a 32-bit int.
FIRST_TYPE_ID = 1 << 16


def field_shape(ros_type):
    """The FieldShape storage reads of a field of ros_type."""
    base_type, is_array, array_length = parse_type(ros_type)
    return FieldShape(ros_type, base_type == 'string', is_array and array_length is None)


def type_id(full_name):
    """A deterministic type ID derived from the full type name alone."""
    span = (1 << 31) - FIRST_TYPE_ID
    return FIRST_TYPE_ID + zlib.crc32(full_name.encode('utf-8')) % span


def gencpp_definition_text(full_text):
    """The definition text as gencpp (and so roscpp's TCPROS handshake) gives it:
    genmsg's full text with every line, the last included, ending in '\\n'."""
    return ''.join(line + '\n' for line in full_text.splitlines() or [''])


class Constant:
    """A constant of a message: its type, name, value, line and comment."""

    def __init__(self, genmsg_constant, line, comment=()):
        self.name = genmsg_constant.name
        self.ros_type = genmsg_constant.type
        self.value = genmsg_constant.val
        self.is_string = self.ros_type == 'string'
        self.is_float = self.ros_type in FLOAT_TYPES
        self.is_integer = not self.is_string and not self.is_float
        self.line = line
        self.comment = list(comment)  # the .msg's comment lines


class ElementType:
    """A field's element type, arrays aside: its wire sizes, and the message
    it is when it is one (None for a built-in type)."""

    def __init__(self, ros_type, min_size, max_size, unbounded_reason=None, message=None):
        self.ros_type = ros_type
        self.min_size = min_size
        self.max_size = max_size  # None: no maximum
        self.unbounded_reason = unbounded_reason
        self.message = message


def _array_max_size(element, count, counted):
    if element.max_size is None:
        return None
    return (ARRAY_COUNT_SIZE if counted else 0) + element.max_size * count


class Field:
    """A field of a message: its type, its bounds, its size on the wire and
    its comment."""

    def __init__(self, name, ros_type, element, bounds, line, comment=()):
        self.name = name
        self.ros_type = ros_type
        self.line = line
        self.comment = list(comment)  # the .msg's comment lines
        self.element = element
        self.bounds = bounds
        base_type, self.is_array, self.array_length = parse_type(ros_type)
        self.element_type = base_type
        self.is_fixed_array = self.is_array and self.array_length is not None
        self.is_variable_array = self.is_array and self.array_length is None
        if not self.is_array:
            self.min_size = element.min_size
            self.max_size = element.max_size
        elif self.is_fixed_array:
            self.min_size = element.min_size * self.array_length
            self.max_size = _array_max_size(element, self.array_length, counted=False)
        else:
            self.min_size = ARRAY_COUNT_SIZE
            self.max_size = (None if bounds.max_count is None
                             else _array_max_size(element, bounds.max_count, counted=True))
        # Where the size has no maximum, as a path to the field that has none:
        # 'header.frame_id (string)'.
        self.unbounded_reason = None
        if self.max_size is None and element.unbounded_reason is not None and (
                not self.is_array or self.is_fixed_array):
            self.unbounded_reason = '%s%s.%s' % (name, '[]' if self.is_array else '',
                                                 element.unbounded_reason)
        elif self.max_size is None:
            self.unbounded_reason = '%s (%s)' % (name, ros_type)


class Message:
    """One message type (or one half of a service)."""

    def __init__(self, full_name, spec, identities, declarations, element_of, storage,
                 definition_text=DEFAULT_DEFINITION_TEXT):
        self.full_name = full_name
        self.package, self.name = full_name.split('/', 1)
        self.source = declarations.path
        self.definition_file = Definition(self.package, self.source)
        self._identities = identities
        self.compact_definition = definition_text == 'compact'
        self.type_id = type_id(full_name)
        self.comment = declarations.type_comment  # the .msg's comment lines about the type
        self.constants = [Constant(constant, line, declarations.comments[line]) for constant, line
                          in zip(spec.constants, declarations.constant_lines)]
        self.fields = []
        for name, ros_type, line in zip(spec.names, spec.types, declarations.field_lines):
            bounds = storage.field_bounds(full_name, name, field_shape(ros_type), self.source,
                                          line)
            self.fields.append(Field(name, ros_type, element_of(ros_type, bounds), bounds, line,
                                     declarations.comments[line]))
        self.dependencies = sorted({f.element_type for f in self.fields if '/' in f.element_type})
        self.min_size = sum(f.min_size for f in self.fields)
        unbounded = [f for f in self.fields if f.max_size is None]
        # The largest wire image, where one exists: fixed-size types, and every
        # type in bounded storage.
        self.max_size = None if unbounded else sum(f.max_size for f in self.fields)
        self.is_fixed_size = self.max_size == self.min_size
        self.unbounded_reason = unbounded[0].unbounded_reason if unbounded else None
        if self.min_size > MAX_MESSAGE_SIZE:
            raise GenmrosError('%s takes at least %d bytes on the wire, more than the %d a '
                               'message can have' % (full_name, self.min_size, MAX_MESSAGE_SIZE),
                               self.source)
        if self.max_size is not None and self.max_size > MAX_MESSAGE_SIZE:
            raise GenmrosError('%s can take %d bytes on the wire, more than the %d a message can '
                               'have' % (full_name, self.max_size, MAX_MESSAGE_SIZE), self.source)
        # genmsg checks field names but takes any text before '=' as a constant's name.
        for constant in self.constants:
            if not is_valid_msg_field_name(constant.name):
                raise GenmrosError("'%s' is not a legal constant name" % constant.name,
                                   self.source, constant.line)

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
    def full_definition(self):
        """The full definition text, as roscpp and rospy send it, whatever
        text this firmware's header carries."""
        return gencpp_definition_text(self._identities.full_text(self.full_name, False))


class Service:
    """A service: its request and response messages and the service's own identity."""

    def __init__(self, full_name, spec, identities, request, response):
        self.full_name = full_name
        self.package, self.name = full_name.split('/', 1)
        self.source = request.source
        self.definition_file = request.definition_file
        self.md5sum = identities.service_md5(spec)
        self.request = request
        self.response = response
        self.dependencies = request.dependencies + response.dependencies


class ModelBuilder:
    """Turns specs loaded by a :class:`colcon_mros.ros1.parse.SpecLoader` into models."""

    def __init__(self, loader, storage=None, definition_text=DEFAULT_DEFINITION_TEXT):
        self.loader = loader
        self.storage = storage or HeapStorage()
        self.definition_text = definition_text
        self._messages = {}

    def message(self, full_name):
        """The model of a loaded message type, built once, after the models
        of the types it contains (without recursion: types nest deeply)."""
        if full_name not in self._messages:
            for name in self.loader.identities.contained_first(full_name, self._messages):
                spec = self.loader.context.get_registered(name)
                self._messages[name] = Message(
                    name, spec, self.loader.identities, self.loader.declarations(name),
                    self._element, self.storage, self.definition_text)
        return self._messages[full_name]

    def service(self, spec):
        return Service(spec.full_name, spec, self.loader.identities,
                       self.message(spec.request.full_name),
                       self.message(spec.response.full_name))

    def closure(self, full_names):
        """The messages named and every message they contain, each after the
        ones it contains (in the order of their sorted names)."""
        names = contained_first(full_names, lambda name: self.message(name).dependencies)
        return [self.message(name) for name in names]

    def _element(self, ros_type, bounds):
        """The :class:`ElementType` of a field's type, arrays aside."""
        base_type = parse_type(ros_type)[0]
        if base_type == 'string':
            maximum = None if bounds.max_size is None else STRING_MIN_SIZE + bounds.max_size
            return ElementType(base_type, STRING_MIN_SIZE, maximum)
        if base_type in BUILTIN_SIZES:
            size = BUILTIN_SIZES[base_type]
            return ElementType(base_type, size, size)
        nested = self._messages[base_type]  # built before the type that contains it
        return ElementType(base_type, nested.min_size, nested.max_size, nested.unbounded_reason,
                           nested)
