# SPDX-License-Identifier: BSD-3-Clause
"""The ROS 2 type model: what the mros2 back end needs of a message.

Built from rosidl's definitions (:mod:`colcon_mros.ros2.parse`): members and
constants with their lines and comments, each member's element (a number,
a string, a wstring or a nested message) and container (none, ``T[N]``,
``T[<=N]``, ``T[]``), defaults, and the bounds of bounded storage
(:mod:`colcon_mros.core.storage`, the same options files as the ROS 1
side). It also knows the CDR sizes: XCDR1 aligns each number to its size
from the start of the stream, so the smallest and largest image of a
message is found by walking its members from position 0, never by adding
per-type sizes. C++ spelling is :mod:`colcon_mros.mros2.cpp`'s job.
"""

from colcon_mros.core.closure import contained_first
from colcon_mros.core.storage import FieldShape
from colcon_mros.errors import GenmrosError, close_match
from colcon_mros.ros2.interfaces import where_packages_come_from
from colcon_mros.ros2.parse import parse_interface

# rosidl's IDL number types: their CDR size, which is also their alignment.
NUMBER_SIZES = {
    'boolean': 1, 'octet': 1, 'char': 1, 'int8': 1, 'uint8': 1,
    'int16': 2, 'uint16': 2, 'int32': 4, 'uint32': 4, 'int64': 8, 'uint64': 8,
    'float': 4, 'double': 8,
}
# What mros2 cannot carry and rosidl can express: said in one line.
UNSUPPORTED_NUMBERS = {
    'wchar': 'wchar has no agreed CDR size between ROS 2 serializers',
    'long double': 'long double has no fixed size on the boards mros2 runs on',
}
LENGTH_SIZE = 4    # the uint32 before a string or a sequence
WCHAR_SIZE = 4     # Fast-CDR writes each wstring character as a 32-bit unit
# Every message image, with mros2's 4-byte header, fits a uint32_t.
MAX_IMAGE_SIZE = (1 << 32) - 1 - 4


class UncarriableType(GenmrosError):
    """Valid IDL that mros2 cannot carry (a wchar, a long double, an image
    larger than a message can be). type_name is the type it was found in
    ('pkg/msg/Name'): a type that contains that one cannot be carried either."""

    def __init__(self, type_name, problem, path=None, line=None):
        self.type_name = type_name
        super().__init__(problem, path, line)


def _align(position, size):
    return position + (-position % size)


class Constant:
    """A constant: name, IDL type (a number or 'string'), value."""

    def __init__(self, rosidl_constant):
        from rosidl_parser.definition import AbstractString
        self.name = rosidl_constant.name
        self.is_string = isinstance(rosidl_constant.type, AbstractString)
        self.number_type = None if self.is_string else rosidl_constant.type.typename
        self.value = rosidl_constant.value


class Member:
    """A member: its element and container, default, bounds and wire sizes."""

    def __init__(self, name, comment, element, number_type, string_bound, message, container,
                 count, default):
        self.name = name
        self.comment = comment
        self.element = element            # 'number', 'string', 'wstring' or 'message'
        self.number_type = number_type    # for 'number': rosidl's name ('int32', 'double'...)
        self.string_bound = string_bound  # string<=N: N; for bounded storage, its max_size
        self.message = message            # for 'message': the nested Message
        self.container = container        # None, 'array', 'bounded_sequence' or 'sequence'
        self.count = count                # T[N]: N; T[<=N]: N; T[] in bounded storage: max_count
        self.default = default            # None, a value, or a list for containers

    @property
    def is_sequence(self):
        return self.container in ('bounded_sequence', 'sequence')

    def _element_end(self, position, largest):
        if self.element == 'number':
            size = NUMBER_SIZES[self.number_type]
            return _align(position, size) + size
        if self.element == 'message':
            return self.message.end(position, largest)
        position = _align(position, LENGTH_SIZE) + LENGTH_SIZE
        length = self.string_bound if largest else 0
        if self.element == 'string':
            return position + length + 1  # the NUL
        return position + (length * WCHAR_SIZE)

    def end(self, position, largest):
        """Where this member's image ends when it starts at position: with
        every string and sequence empty, or as long as its bound allows
        (None: no bound)."""
        if largest and self.element in ('string', 'wstring') and self.string_bound is None:
            return None
        if self.container is None:
            return self._element_end(position, largest)
        if self.is_sequence:
            position = _align(position, LENGTH_SIZE) + LENGTH_SIZE
            if not largest:
                return position
            if self.count is None:
                return None
        return self._elements_end(position, self.count, largest)

    def _elements_end(self, position, count, largest):
        """Where count elements starting at position end. An element's end
        depends on its start only modulo 8 (the largest alignment), so once a
        start repeats modulo 8 the rest follows by arithmetic: a
        float64[600000000] costs no more than a float64[2]."""
        seen = {}
        done = 0
        while done < count:
            key = position % 8
            if key in seen:
                first_done, first_position = seen[key]
                period, advance = done - first_done, position - first_position
                cycles = (count - done) // period
                position += cycles * advance
                done += cycles * period
                seen = {}
                if done == count:
                    break
            seen[position % 8] = (done, position)
            position = self._element_end(position, largest)
            if position is None:
                return None
            done += 1
        return position


class Message:
    """One message type, or one half of a service (``Query_Request``)."""

    def __init__(self, package, kind, name, source, comment, members, constants):
        self.package = package
        self.kind = kind  # 'msg', or 'srv' for a service's request and response
        self.name = name
        self.full_name = '%s/%s/%s' % (package, kind, name)
        self.source = source
        self.comment = comment
        self.members = members
        self.constants = constants
        self.dependencies = []
        for member in members:
            if member.message is not None and member.message not in self.dependencies:
                self.dependencies.append(member.message)
        self.min_size = self.end(0, largest=False)
        self.max_size = self.end(0, largest=True)
        if self.min_size > MAX_IMAGE_SIZE:
            raise UncarriableType(
                self.full_name, '%s takes at least %d bytes in CDR, more than the %d a message '
                'can have' % (self.full_name, self.min_size, MAX_IMAGE_SIZE), source)
        if self.max_size is not None and self.max_size > MAX_IMAGE_SIZE:
            raise UncarriableType(
                self.full_name, '%s can take %d bytes in CDR, more than the %d a message can have'
                % (self.full_name, self.max_size, MAX_IMAGE_SIZE), source)

    def end(self, position, largest=False):
        """Where an image of this message that starts at position ends (see
        :meth:`Member.end`); CDR aligns from the stream's start, so a nested
        message's size depends on where it starts."""
        for member in self.members:
            position = member.end(position, largest)
            if position is None:
                return None
        return position


class Service:
    """A service: its request and response messages."""

    def __init__(self, package, name, source, request, response):
        self.package = package
        self.name = name
        self.full_name = '%s/srv/%s' % (package, name)
        self.source = source
        self.request = request
        self.response = response
        self.dependencies = [request, response]


def _default_of(member, element):
    if not member.has_annotation('default'):
        return None
    value = member.get_annotation_value('default')['value']
    if isinstance(value, str) and element == 'wstring':
        # rosidl_adapter writes its IDL as Latin-1: a UTF-8 default comes
        # back as one character per byte.
        try:
            value = value.encode('latin-1').decode('utf-8')
        except (UnicodeEncodeError, UnicodeDecodeError):
            pass
    return value


def _type_text(element, number_type, message, container):
    """A member's type as a .msg spells it, for an error line: 'string', 'int32[]'."""
    base = {'number': number_type, 'message': message and message.name}.get(element, element)
    return base + ('[]' if container == 'sequence' else '')


class ModelBuilder:
    """Builds the models of the types of a set of packages, each once, the
    types they contain first. where_missing(package) says where a package
    not among them would come from."""

    def __init__(self, packages, storage, where_missing=where_packages_come_from):
        self.packages = packages
        self.storage = storage
        self.where_missing = where_missing
        self._parsed = {}
        self._messages = {}
        self._services = {}
        self._building = []

    def _parse(self, interface):
        if interface.path not in self._parsed:
            self._parsed[interface.path] = parse_interface(interface)
        return self._parsed[interface.path]

    def _interface(self, package, kind, name, path=None, line=None):
        if package not in self.packages:
            raise GenmrosError("unknown package '%s' of type '%s/%s/%s' (not in the workspace or "
                               'the installed ROS 2 packages%s; %s)'
                               % (package, package, kind, name,
                                  close_match(package, self.packages),
                                  self.where_missing(package)), path, line)
        try:
            return self.packages[package].interface(kind, name)
        except GenmrosError as error:
            raise GenmrosError(error.problem, path, line)

    def message(self, full_name, path=None, line=None):
        """The Message of 'pkg/msg/Name', 'pkg/Name' or a service half
        'pkg/srv/Name_Request'."""
        parts = full_name.split('/')
        if len(parts) == 2:
            parts = [parts[0], 'msg', parts[1]]
        if len(parts) != 3 or parts[1] not in ('msg', 'srv') or not all(parts):
            raise GenmrosError("bad type name '%s' (expected PKG/msg/TYPE or PKG/TYPE)"
                               % full_name, path, line)
        package, kind, name = parts
        key = '/'.join(parts)
        if key in self._messages:
            return self._messages[key]
        if kind == 'srv':
            service_name, _, half = name.rpartition('_')
            if half not in ('Request', 'Response'):
                raise GenmrosError("'%s' is no half of a service (expected %s/srv/NAME_Request or "
                                   '_Response)' % (full_name, package), path, line)
            service = self.service('%s/srv/%s' % (package, service_name), path, line)
            return service.request if half == 'Request' else service.response
        interface = self._interface(package, kind, name, path, line)
        parsed = self._parse(interface)
        self._messages[key] = self._build(parsed, parsed.messages[0], 0)
        return self._messages[key]

    def service(self, full_name, path=None, line=None):
        package, _, name = full_name.replace('/srv/', '/').partition('/')
        key = '%s/srv/%s' % (package, name)
        if key not in self._services:
            interface = self._interface(package, 'srv', name, path, line)
            parsed = self._parse(interface)
            rosidl_service = parsed.services[0]
            self._services[key] = Service(
                package, name, interface.path,
                self._build(parsed, rosidl_service.request_message, 0),
                self._build(parsed, rosidl_service.response_message, 1))
        return self._services[key]

    def _build(self, parsed, rosidl_message, section):
        structure = rosidl_message.structure
        package, kind = structure.namespaced_type.namespaces[:2]
        name = structure.namespaced_type.name
        full_name = '%s/%s/%s' % (package, kind, name)
        if full_name in self._building:
            raise GenmrosError('%s contains itself (%s)' % (full_name, ' -> '.join(
                self._building[self._building.index(full_name):] + [full_name])), parsed.path)
        self._building.append(full_name)
        try:
            members = [self._member(parsed, full_name, member, section)
                       for member in structure.members]
        finally:
            self._building.pop()
        constants = [Constant(c) for c in rosidl_message.constants]
        return Message(package, kind, name, parsed.path, structure.get_comment_lines(), members,
                       constants)

    def _member(self, parsed, full_name, member, section):
        """The Member of a structure's member, bounded by the storage."""
        from rosidl_parser import definition as idl
        line = parsed.line_of(member.name, section)
        container, count, element_type = None, None, member.type
        if isinstance(member.type, idl.Array):
            container, count, element_type = 'array', member.type.size, member.type.value_type
        elif isinstance(member.type, idl.BoundedSequence):
            container, count = 'bounded_sequence', member.type.maximum_size
            element_type = member.type.value_type
        elif isinstance(member.type, idl.UnboundedSequence):
            container, element_type = 'sequence', member.type.value_type
        number_type = string_bound = message = None
        if isinstance(element_type, idl.BasicType):
            if element_type.typename in UNSUPPORTED_NUMBERS:
                raise UncarriableType(full_name, "member '%s': %s" % (
                    member.name, UNSUPPORTED_NUMBERS[element_type.typename]), parsed.path, line)
            element, number_type = 'number', element_type.typename
        elif isinstance(element_type, idl.AbstractGenericString):
            element = 'wstring' if isinstance(element_type, idl.AbstractWString) else 'string'
            if element_type.has_maximum_size():
                string_bound = element_type.maximum_size
        elif isinstance(element_type, idl.NamespacedType):
            package, kind = element_type.namespaces[:2]
            element = 'message'
            message = self.message('%s/%s/%s' % (package, kind, element_type.name),
                                   parsed.path, line)
        else:
            raise UncarriableType(full_name, "member '%s' has a type mros2 cannot carry"
                                  % member.name, parsed.path, line)
        # Bounded storage bounds what rosidl leaves unbounded, from the options files.
        pkg, _, type_name = full_name.split('/')
        unbounded_string = element in ('string', 'wstring') and string_bound is None
        bounds = self.storage.field_bounds(
            '%s/%s' % (pkg, type_name), member.name,
            FieldShape(_type_text(element, number_type, message, container), unbounded_string,
                       container == 'sequence'), parsed.path, line)
        if string_bound is None:
            string_bound = bounds.max_size
        if container == 'sequence':
            count = bounds.max_count
        return Member(member.name, member.get_comment_lines(), element, number_type, string_bound,
                      message, container, count, _default_of(member, element))

    def closure(self, roots):
        """The messages roots are and contain, each after the ones it contains."""
        return contained_first(roots, lambda message: message.dependencies)
