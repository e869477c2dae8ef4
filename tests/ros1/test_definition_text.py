# SPDX-License-Identifier: BSD-3-Clause
"""The compact definition text: the same type to every ROS tool.

For every Debian message type and every test_ws type, the compact text loads
with genpy's dynamic message loader (what rosbag and ``rostopic echo`` use for
a type they do not have) into classes with the MD5 sum and field layout of
the full text's, which decode roscpp's wire images (ros::serialization, on
the host) to the same values and encode those to the same bytes. The
export, the CMake module and the make fragment carry the choice into headers.
"""

import glob
import io
import os
import re
import subprocess

import pytest

from genpy.dynamic import generate_dynamic

from support import cpp_harness
from support.build_integration import user_environment
from support.checkout import REPO, TEST_WS, run_genmros
from support.debian_messages import DEBIAN_MESSAGE_PACKAGES

from colcon_mros.export.export_dir import ExportDir
from colcon_mros.integrations.installed_files import CMAKE_MODULE, installed_file
from colcon_mros.mros_v1.names import RESERVED_NAMES
from colcon_mros.ros1.identity import compact_text
from colcon_mros.ros1.model import gencpp_definition_text
from colcon_mros.ros1.parse import SpecLoader
from colcon_mros.ros1.workspace import installed_packages
from testing.ros_paths import prefix_arguments, ros1_definitions, ros1_prefixes

SEEDS = 6  # per type: binary, text and compact instances, twice


def _encode(message):
    """genpy's wire image of message."""
    buffer = io.BytesIO()
    message.serialize(buffer)
    return buffer.getvalue()


def test_compact_text_keeps_declarations_only():
    text = ('# A comment\n\nHeader   header   # the stamp\n  float64[36]\tcovariance\n'
            'int32 A = 5 # five\nstring S=a # kept: part of the value\n'
            'string  T = x\n#string NOT=a constant\nuint8 B=1\n')
    assert compact_text(text) == ('Header header\nfloat64[36]\tcovariance\nint32 A=5\n'
                                  'string S=a # kept: part of the value\nstring  T = x\nuint8 B=1')


def _type_names():
    loader = SpecLoader(cpp_harness.search_path(), RESERVED_NAMES)
    names = []
    for package in DEBIAN_MESSAGE_PACKAGES:
        for path in ros1_definitions(package, 'msg'):
            names.append(loader.load_message_file(path, package).full_name)
        for path in ros1_definitions(package, 'srv'):
            spec = loader.load_service_file(path, package)
            names += [spec.request.full_name, spec.response.full_name]
    for package in ('mros_test', 'mros_test_base'):
        for path in sorted(glob.glob(os.path.join(TEST_WS, 'src', package, 'msg', '*.msg'))):
            names.append(loader.load_message_file(path, package).full_name)
        for path in sorted(glob.glob(os.path.join(TEST_WS, 'src', package, 'srv', '*.srv'))):
            spec = loader.load_service_file(path, package)
            names += [spec.request.full_name, spec.response.full_name]
    return loader, names


@pytest.fixture(scope='module')
def roscpp_images(tmp_path_factory):
    """{type: [wire image, ...]}: roscpp's images of random instances of every
    Debian and test_ws message type, and the genmros loader of those types."""
    loader, names = _type_names()
    root = tmp_path_factory.mktemp('definition_text')
    search_path = cpp_harness.search_path()
    test_ws_services = [(p, f) for p in ('mros_test', 'mros_test_base')
                        for f in sorted(glob.glob(os.path.join(TEST_WS, 'src', p, 'srv',
                                                               '*.srv')))]
    debian_services = [(p, f) for p in DEBIAN_MESSAGE_PACKAGES
                       for f in ros1_definitions(p, 'srv')]
    type_set = cpp_harness.TypeSet(search_path,
                                   [n for n in names if not n.endswith(('Request', 'Response'))],
                                   debian_services + test_ws_services)
    _, program = cpp_harness.expected_bytes_program(type_set, search_path, root)
    modes = [cpp_harness.BINARY, cpp_harness.TEXT, cpp_harness.COMPACT]
    output = subprocess.run([program, str(SEEDS)] + [str(mode) for mode in modes], check=True,
                            capture_output=True, text=True).stdout
    images = {}
    for line in output.splitlines():
        if line.startswith('case '):
            _, name, _, _, size, wire = line.split(' ')
            images.setdefault(name, []).append(bytes.fromhex(wire) if int(size) else b'')
    return loader, names, images


def _values(message):
    """A message's values as plain data; floats by repr, so NaN equals NaN."""
    if hasattr(message, '__slots__'):
        return tuple((slot, _values(getattr(message, slot))) for slot in message.__slots__)
    if isinstance(message, (list, tuple)):
        return [_values(item) for item in message]
    if isinstance(message, float):
        return repr(message)
    return message


def _class(name, text):
    return generate_dynamic(name, text)[name]


def test_compact_text_is_the_same_type_to_genpy(roscpp_images):
    loader, names, images = roscpp_images
    assert len(names) >= 190  # 181 Debian types and service halves, and test_ws's
    assert len([n for n in names if n in images]) == len(names)
    compared = 0
    for name in names:
        full_text = gencpp_definition_text(loader.identities.full_text(name))
        compact = gencpp_definition_text(loader.identities.full_text(name, compact=True))
        assert not re.search(r'^\s*#', compact, re.M), name
        full_class, compact_class = _class(name, full_text), _class(name, compact)
        assert compact_class._md5sum == full_class._md5sum == loader.identities.md5_of(name), name
        assert compact_class._type == name
        assert (compact_class.__slots__, compact_class._slot_types) == \
            (full_class.__slots__, full_class._slot_types), name
        assert compact_class._has_header == full_class._has_header, name
        for wire in images[name]:
            from_full, from_compact = full_class(), compact_class()
            from_full.deserialize(wire)
            from_compact.deserialize(wire)
            assert _values(from_compact) == _values(from_full), name
            # genpy decodes strings as UTF-8, replacing what is not: binary
            # strings come back changed, the same way from either class.
            assert _encode(from_compact) == _encode(from_full), name
            compared += 1
    assert compared == len(names) * SEEDS


def test_compact_text_is_at_most_forty_percent_of_full(roscpp_images):
    loader, names, _ = roscpp_images
    debian = [n for n in names if n.split('/')[0] in DEBIAN_MESSAGE_PACKAGES]
    full = sum(len(gencpp_definition_text(loader.identities.full_text(n))) for n in debian)
    compact = sum(len(gencpp_definition_text(loader.identities.full_text(n, True)))
                  for n in debian)
    assert compact <= 0.4 * full, (compact, full)


def _definition_in_header(header_path):
    """The definition text a header's Definition trait returns, read from
    its C string literal pieces."""
    with open(header_path) as header:
        text = header.read()
    body = text.split('struct Definition<', 1)[1].split(';', 1)[0]
    pieces = re.findall(r'^\s+"((?:[^"\\]|\\.)*)"$', body, re.M)
    return ''.join(pieces).encode().decode('unicode_escape')


def test_export_writes_the_chosen_text_into_every_header(tmp_path):
    run_genmros('mros-v1-export', *prefix_arguments(ros1_prefixes()), '--type',
                'nav_msgs/Odometry', '-o', str(tmp_path / 'full'))
    run_genmros('mros-v1-export', *prefix_arguments(ros1_prefixes()),
                '--type', 'nav_msgs/Odometry', '-o', str(tmp_path / 'compact'),
                '--definition-text', 'compact')
    for relative in ('nav_msgs/Odometry.h', 'std_msgs/Header.h',
                     'geometry_msgs/PoseWithCovariance.h'):
        name = relative[:-2]
        full = _definition_in_header(str(tmp_path / 'full' / relative))
        compact = _definition_in_header(str(tmp_path / 'compact' / relative))
        assert '#' in full and '#' not in compact
        assert _class(name, compact)._md5sum == _class(name, full)._md5sum
        with open(str(tmp_path / 'compact' / relative)) as header:
            assert 'without comments and\n// blank lines' in header.read()
    result = run_genmros('mros-v1-export', *prefix_arguments(ros1_prefixes()),
                         '--type', 'std_msgs/Header',
                         '-o', str(tmp_path / 'bad'), '--definition-text', 'short',
                         check=False)
    assert result.returncode == 2 and "invalid choice: 'short'" in result.stderr


def test_cmake_module_and_make_fragment_take_the_choice(tmp_path):
    project = tmp_path / 'firmware'
    project.mkdir()
    (project / 'main.cpp').write_text('#include <std_msgs/Header.h>\nint main() { return 0; }\n')
    (project / 'CMakeLists.txt').write_text(
        'cmake_minimum_required(VERSION 3.10)\nproject(f CXX)\n'
        'include(%s/cmake/mros_generate.cmake)\n'
        'add_executable(generated main.cpp)\n'
        'mros_generate_messages(TARGET generated TYPES std_msgs/Header PACKAGE_PATHS %s '
        'DEFINITION_TEXT compact)\n'
        'add_executable(imported main.cpp)\n'
        'mros_import_messages(TARGET imported EXPORT_DIR %s TYPES std_msgs/Header '
        'DEFINITION_TEXT compact)\n'
        'add_executable(bad main.cpp)\n'
        'if(BAD)\n'
        '  mros_generate_messages(TARGET bad TYPES std_msgs/Header DEFINITION_TEXT short)\n'
        'endif()\n'
        % (REPO, ' '.join(ros1_prefixes()), tmp_path / 'export'))
    # An export dir as colcon writes it: full-text headers and the definitions.
    export = ExportDir(str(tmp_path / 'export'))
    run_genmros('mros-v1-export', *prefix_arguments(ros1_prefixes()), '--package', 'std_msgs',
                '--only', 'headers', '-o', export.include_dir)
    export.replace_packages({'std_msgs': installed_packages(ros1_prefixes())['std_msgs']},
                            installed_file(CMAKE_MODULE))
    build = tmp_path / 'build'
    # The builds run this checkout's genmros, not the one installed on PATH.
    environment = user_environment()
    subprocess.run(['cmake', '-S', str(project), '-B', str(build)],
                   check=True, capture_output=True, env=environment)
    subprocess.run(['cmake', '--build', str(build)], check=True, capture_output=True,
                   env=environment)
    for target in ('generated', 'imported'):
        compact = _definition_in_header(
            str(build / 'mros_messages' / target / 'std_msgs' / 'Header.h'))
        assert compact == 'uint32 seq\ntime stamp\nstring frame_id\n', target
    bad = subprocess.run(['cmake', '-S', str(project), '-B', str(build), '-DBAD=ON'],
                         capture_output=True, text=True, env=environment)
    assert bad.returncode != 0
    assert ("mros_generate_messages(): genmros mros-v1-export: error: argument --definition-text: "
            "invalid choice: 'short' (choose from 'full', 'compact')") in ' '.join(
                bad.stderr.split())

    app = tmp_path / 'app'
    app.mkdir()
    (app / 'Makefile').write_text(
        'MROS_MSG_TYPES := std_msgs/Header\nMROS_MSG_PATHS := %s\n'
        'MROS_MSG_DEFINITION_TEXT := compact\ninclude %s/cmake/genmros.mk\nall:\n\t@true\n'
        % (' '.join(ros1_prefixes()), REPO))
    subprocess.run(['make', '-C', str(app)], check=True, capture_output=True, env=environment)
    assert _definition_in_header(str(app / 'include' / 'std_msgs' / 'Header.h')) == \
        'uint32 seq\ntime stamp\nstring frame_id\n'
