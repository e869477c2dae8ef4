# SPDX-License-Identifier: BSD-3-Clause
"""ROS 2 messages as the mros2 tests, benchmarks and evaluation see them
from outside the generated code: random instances of a type of genmros'
ROS 2 model (:mod:`colcon_mros.ros2.model`), the same instance as Fast-CDR
ops (:mod:`testing.fastcdr`) and as a rosbags message, and ROS 2 packages
written from rosbags' type store, whose definitions of std_msgs,
geometry_msgs and sensor_msgs are ROS 2's own.

A value is a dict {member name: value}: numbers as int, float or bool,
strings as str (UTF-8 on the wire), sequences and arrays as lists, nested
messages as dicts.
"""

import os
import struct

# rosidl's number types and their Fast-CDR op kinds; the ranges of the integers.
OP_KINDS = {
    'boolean': 'bool', 'octet': 'octet', 'char': 'uint8', 'int8': 'int8', 'uint8': 'uint8',
    'int16': 'int16', 'uint16': 'uint16', 'int32': 'int32', 'uint32': 'uint32',
    'int64': 'int64', 'uint64': 'uint64', 'float': 'float32', 'double': 'float64',
}
_INTEGER_BITS = {'octet': (8, False), 'char': (8, False), 'int8': (8, True), 'uint8': (8, False),
                 'int16': (16, True), 'uint16': (16, False), 'int32': (32, True),
                 'uint32': (32, False), 'int64': (64, True), 'uint64': (64, False)}
# Characters random strings draw from: ASCII, two-byte and three-byte UTF-8.
_TEXT = 'abcXYZ019 _-/:' + '\u00e9\u00fc' + '\u30cf\u30ed'
MAX_RANDOM_ELEMENTS = 4
MAX_RANDOM_STRING = 12


def float32(value):
    return struct.unpack('<f', struct.pack('<f', value))[0]


def _random_number(number_type, rng):
    if number_type == 'boolean':
        return rng.random() < 0.5
    if number_type in ('float', 'double'):
        value = rng.choice([0.0, -0.0, 1.5, -2.25, rng.uniform(-1e6, 1e6),
                            rng.uniform(-1, 1) * 10 ** rng.randint(-30, 30)])
        return float32(value) if number_type == 'float' else value
    bits, signed = _INTEGER_BITS[number_type]
    low, high = (-(1 << (bits - 1)), (1 << (bits - 1)) - 1) if signed else (0, (1 << bits) - 1)
    return rng.choice([low, high, 0, rng.randint(low, high)])


def _random_text(bound, rng):
    length = rng.randint(0, MAX_RANDOM_STRING if bound is None else min(bound, MAX_RANDOM_STRING))
    text = ''.join(rng.choice(_TEXT) for _ in range(length))
    while bound is not None and len(text.encode('utf-8')) > bound:
        text = text[:-1]
    return text


def _random_element(member, rng):
    if member.element == 'number':
        return _random_number(member.number_type, rng)
    if member.element == 'message':
        return random_value(member.message, rng)
    return _random_text(member.string_bound, rng)


def random_value(message, rng):
    """A random instance of message, within every bound it has."""
    value = {}
    for member in message.members:
        if member.container is None:
            value[member.name] = _random_element(member, rng)
            continue
        if member.container == 'array':
            count = member.count
        else:
            limit = MAX_RANDOM_ELEMENTS if member.count is None else min(member.count,
                                                                         MAX_RANDOM_ELEMENTS)
            count = rng.randint(0, limit)
        value[member.name] = [_random_element(member, rng) for _ in range(count)]
    return value


def _element_ops(member, element):
    if member.element == 'number':
        return [(OP_KINDS[member.number_type], element)]
    if member.element == 'message':
        return fastcdr_ops(member.message, element)
    if member.element == 'wstring':
        return [('wstring', element)]
    return [('string', element.encode('utf-8'))]


def fastcdr_ops(message, value):
    """The Fast-CDR calls that serialize value, in wire order."""
    ops = []
    for member in message.members:
        item = value[member.name]
        if member.container is None:
            ops += _element_ops(member, item)
            continue
        if member.is_sequence:
            ops.append(('count', len(item)))
        for element in item:
            ops += _element_ops(member, element)
    return ops


def value_from_ops(message, decoded):
    """The value Fast-CDR's decoded op values (an iterator, in fastcdr_ops'
    order) stand for: the inverse of fastcdr_ops."""
    value = {}
    for member in message.members:
        def element():
            if member.element == 'message':
                return value_from_ops(member.message, decoded)
            item = next(decoded)
            return item.decode('utf-8') if member.element == 'string' else item
        if member.container is None:
            value[member.name] = element()
        else:
            count = next(decoded) if member.is_sequence else member.count
            value[member.name] = [element() for _ in range(count)]
    return value


def op_kinds(ops):
    return [kind for kind, _ in ops]


def has_wstring(message):
    """Whether message or a message it contains has a wstring (rosbags has none)."""
    return any(m.element == 'wstring' or (m.element == 'message' and has_wstring(m.message))
               for m in message.members)


def _signed_byte(value):
    return value - 256 if value > 127 else value


def rosbags_message(typestore, message, value):
    """value as a rosbags message object of typestore. rosbags takes byte
    (rosidl's octet) as int8, ROS 2 as uint8: the same bits."""
    import numpy
    fields = {}
    for member in message.members:
        item = value[member.name]
        if member.number_type == 'octet':
            item = [_signed_byte(v) for v in item] if member.container else _signed_byte(item)
        if member.element == 'message':
            item = ([rosbags_message(typestore, member.message, e) for e in item]
                    if member.container else rosbags_message(typestore, member.message, item))
        elif member.element == 'number' and member.container:
            dtype = {'boolean': numpy.bool_, 'float': numpy.float32, 'double': numpy.float64,
                     'octet': numpy.int8, 'char': numpy.uint8}.get(member.number_type,
                                                                   member.number_type)
            item = numpy.array(item, dtype=dtype)
        fields[member.name] = item
    return typestore.types[message.full_name](**fields)


# rosbags' base type names -> .msg's.
def _msg_type(node, typestore_name):
    from rosbags.typesys.base import Nodetype
    kind, detail = node
    if kind == Nodetype.BASE:
        name, bound = detail
        return '%s<=%d' % (name, bound) if bound else name
    if kind == Nodetype.NAME:
        return detail.replace('/msg/', '/')
    element, count = detail
    element_text = _msg_type(element, typestore_name)
    if kind == Nodetype.ARRAY:
        return '%s[%d]' % (element_text, count)
    return '%s[<=%d]' % (element_text, count) if count else '%s[]' % element_text


def write_packages(typestore, names, root):
    """Write ROS 2 packages under root/src holding the .msg files of names
    and of every type they contain, from typestore's definitions; returns
    the workspace root."""
    pending = list(names)
    written = set()
    while pending:
        name = pending.pop()
        if name in written:
            continue
        written.add(name)
        constants, fields = typestore.fielddefs[name]
        package, _, type_name = name.split('/')
        lines = ['%s %s=%r' % (ctype, cname, cvalue) if not isinstance(cvalue, str)
                 else '%s %s=%s' % (ctype, cname, cvalue) for cname, ctype, cvalue in constants]
        for field_name, node in fields:
            if field_name == 'structure_needs_at_least_one_member':
                continue  # rosidl adds it to an empty message itself
            lines.append('%s %s' % (_msg_type(node, name), field_name))
            pending.extend(_contained(node))
        directory = os.path.join(root, 'src', package)
        os.makedirs(os.path.join(directory, 'msg'), exist_ok=True)
        with open(os.path.join(directory, 'msg', type_name + '.msg'), 'w') as stream:
            stream.write('\n'.join(lines) + '\n')
        with open(os.path.join(directory, 'package.xml'), 'w') as stream:
            stream.write(PACKAGE_XML % package)
    return root


def _contained(node):
    from rosbags.typesys.base import Nodetype
    kind, detail = node
    if kind == Nodetype.NAME:
        return [detail]
    if kind in (Nodetype.ARRAY, Nodetype.SEQUENCE):
        return _contained(detail[0])
    return []


PACKAGE_XML = '''<?xml version="1.0"?>
<package format="3">
  <name>%s</name>
  <version>0.0.0</version>
  <description>Written from rosbags' type store for a test</description>
  <maintainer email="dev@example.com">dev</maintainer>
  <license>Apache-2.0</license>
  <buildtool_depend>ament_cmake</buildtool_depend>
  <member_of_group>rosidl_interface_packages</member_of_group>
  <export><build_type>ament_cmake</build_type></export>
</package>
'''
