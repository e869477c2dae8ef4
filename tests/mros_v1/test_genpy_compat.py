# SPDX-License-Identifier: BSD-3-Clause
"""genmros headers against genpy (rospy's message classes) for the test_ws types.

genpy generates Python classes from the same .msg files; bytes made by either
side must be read back by the other and re-encoded unchanged.
"""

import glob
import importlib
import io
import os
import random
import struct
import subprocess
import sys

import genpy
import pytest
from genmsg.msgs import parse_type

from support import cpp_harness
from support.checkout import TEST_WS
from testing import ros_paths

INSTANCES_PER_TYPE = 100


def _workspace_definitions():
    for package_dir in sorted(glob.glob(os.path.join(TEST_WS, 'src', '*'))):
        package = os.path.basename(package_dir)
        for kind in ('msg', 'srv'):
            paths = sorted(glob.glob(os.path.join(package_dir, kind, '*.' + kind)))
            if paths:
                yield package, kind, paths


@pytest.fixture(scope='module')
def genpy_classes(tmp_path_factory):
    """Runs the real genpy generators over test_ws; puts the result on sys.path."""
    root = str(tmp_path_factory.mktemp('genpy'))
    flags = []
    for package, directories in cpp_harness.search_path().items():
        flags += ['-I', '%s:%s' % (package, directories[0])]
    for package, kind, paths in _workspace_definitions():
        output = os.path.join(root, package, kind)
        generator = ros_paths.genpy()[0 if kind == 'msg' else 1]
        for path in paths:
            subprocess.run([sys.executable, generator, path, '-p',
                           package, '-o', output] + flags, check=True)
        subprocess.run([sys.executable, generator, '--initpy',
                       '-p', package, '-o', output], check=True)
        open(os.path.join(root, package, '__init__.py'), 'a').close()
    sys.path.insert(0, root)
    yield
    sys.path.remove(root)


@pytest.fixture(scope='module')
def probe(test_ws_export, tmp_path_factory):
    """The C++ probe over genmros' test_ws headers (portable byte order path), and
    the type names it indexes."""
    messages = ['%s/%s' % (package, os.path.basename(p)[:-4])
                for package, kind, paths in _workspace_definitions()
                if kind == 'msg' for p in paths]
    services = [(package, p) for package, kind, paths in _workspace_definitions()
                if kind == 'srv' for p in paths]
    type_set = cpp_harness.TypeSet(cpp_harness.search_path(), messages, services)
    directory = str(tmp_path_factory.mktemp('probe'))
    sources = cpp_harness.write_sources(directory, type_set, with_roscpp=False)
    # The byte-by-byte path that big-endian hosts take; the roscpp comparison covers the other.
    objects = [cpp_harness.compile_object(sources['mros_side.cpp'], directory,
                                          [test_ws_export, directory],
                                          flags=['-DMROS_WIRE_PORTABLE']),
               cpp_harness.compile_object(os.path.join(cpp_harness.RANDOM_HEADER_DIR, 'probe.cpp'),
                                          directory, [])]
    program = cpp_harness.link_program(objects, os.path.join(directory, 'probe'))
    process = subprocess.Popen([program], stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True)
    try:
        yield process, type_set.messages
    finally:
        process.stdin.close()
        process.wait(timeout=10)


def _ask(process, command):
    process.stdin.write(command + '\n')
    process.stdin.flush()
    return process.stdout.readline().split()


def _hex(data):
    return data.hex() or '-'


def _message_class(full_name):
    """genpy's class for a type; the halves of a service live in the package's srv module."""
    package, name = full_name.split('/')
    for module in ('msg', 'srv'):
        classes = importlib.import_module('%s.%s' % (package, module))
        if hasattr(classes, name):
            return getattr(classes, name)
    raise LookupError(full_name)


def _random_scalar(ros_type, rng):
    if ros_type == 'bool':
        return rng.random() < 0.5
    if ros_type in ('int8', 'int16', 'int32', 'int64', 'byte'):
        bits = {'byte': 8}.get(ros_type) or int(ros_type[3:])
        return rng.choice([-(1 << (bits - 1)), (1 << (bits - 1)) - 1, 0,
                           rng.randrange(-(1 << (bits - 1)), 1 << (bits - 1))])
    if ros_type in ('uint8', 'uint16', 'uint32', 'uint64', 'char'):
        bits = {'char': 8}.get(ros_type) or int(ros_type[4:])
        return rng.choice([0, (1 << bits) - 1, rng.randrange(1 << bits)])
    if ros_type == 'float32':
        return struct.unpack('<f', struct.pack('<f', rng.uniform(-1e6, 1e6)))[0]
    if ros_type == 'float64':
        return rng.choice([rng.uniform(-1e300, 1e300), float('-inf'), 5e-324, 0.0])
    if ros_type == 'string':
        return ''.join(rng.choice('aZ0 é€\n"') for _ in range(rng.choice([0, 1, 5, 30])))
    if ros_type == 'time':
        return genpy.Time(rng.randrange(1 << 32), rng.randrange(10 ** 9))
    if ros_type == 'duration':
        return genpy.Duration(rng.randrange(-(1 << 31), 1 << 31), rng.randrange(10 ** 9))
    return _random_message(_message_class(ros_type), rng)


def _random_value(ros_type, rng):
    base, is_array, length = parse_type(ros_type)
    if not is_array:
        return _random_scalar(base, rng)
    count = length if length is not None else rng.choice([0, 1, 2, 4, 50])
    values = [_random_scalar(base, rng) for _ in range(count)]
    if base in ('uint8', 'char'):
        return bytes(values)  # genpy holds uint8[] and char[] as bytes
    return values


def _random_message(cls, rng):
    message = cls()
    # genpy qualifies every type
    for name, ros_type in zip(message.__slots__, message._slot_types):
        setattr(message, name, _random_value(ros_type, rng))
    return message


def _encode(message):
    buffer = io.BytesIO()
    message.serialize(buffer)
    return buffer.getvalue()


def test_identity_equals_genpy(genpy_classes, test_ws_export):
    from mros_test.msg import NestedTypes
    with open(os.path.join(test_ws_export, 'mros_test', 'NestedTypes.h')) as header:
        text = header.read()
    assert '"%s"' % NestedTypes._md5sum in text
    assert '"mros_test/NestedTypes"' in text


def test_genpy_reads_genmros_bytes(genpy_classes, probe):
    process, types = probe
    checked = 0
    for index, full_name in enumerate(types):
        cls = _message_class(full_name)
        for seed in range(INSTANCES_PER_TYPE):
            ours = bytes.fromhex(_ask(process, 'sample %d %d' % (index, seed))[0].replace('-', ''))
            message = cls()
            message.deserialize(ours)
            assert _encode(message) == ours, '%s seed %d' % (full_name, seed)
            checked += 1
    assert checked == len(types) * INSTANCES_PER_TYPE


def test_genmros_reads_genpy_bytes(genpy_classes, probe):
    process, types = probe
    rng = random.Random(20261121)
    for index, full_name in enumerate(types):
        cls = _message_class(full_name)
        for instance in range(INSTANCES_PER_TYPE):
            theirs = _encode(_random_message(cls, rng))
            consumed, reencoded = _ask(process, 'reencode %d %s' % (index, _hex(theirs)))
            assert int(consumed) == len(theirs), '%s instance %d' % (full_name, instance)
            assert reencoded.replace(
                '-', '') == theirs.hex(), '%s instance %d' % (full_name, instance)


def test_personal_data_round_trip(genpy_classes, probe):
    from mros_test.msg import PersonalData
    process, types = probe
    sent = PersonalData(first_name='Phil', last_name='Woods', age=83, score=100000)
    wire = _encode(sent)
    consumed, reencoded = _ask(process, 'reencode %d %s' % (
        types.index('mros_test/PersonalData'), wire.hex()))
    assert int(consumed) == len(wire) == 4 + 4 + 4 + 5 + 2 + 4
    received = PersonalData()
    received.deserialize(bytes.fromhex(reencoded))
    assert (received.first_name, received.last_name, received.age,
            received.score) == ('Phil', 'Woods', 83, 100000)
