# SPDX-License-Identifier: BSD-3-Clause
"""genmros headers as a drop-in for the mROS v1 library and its apps.

mROS v1 apps build with make at -std=gnu++98 for ARM boards; the headers must
compile there and in every later standard, deliver frames the way the v1
library hands them over, and come from genmros through the make fragment.
The real library runs with them in test_mros_v1_pc*.py; here the headers
are compiled for the boards' CPUs and made by the make fragment.
"""

import filecmp
import glob
import os
import re
import shutil
import subprocess
import sys

import pytest

from support.compile_checks import (LANGUAGE_MODES, STRICT_FLAGS, TARGETS,
                                    every_header_translation_unit)
from support.checkout import REPO, TEST_WS, run_genmros
from support.settings_headers import define, header_paths, small_settings
from testing.ros_paths import prefix_arguments, ros1_prefixes

# cmake, colcon, catkin or make builds: more than half a minute.
pytestmark = pytest.mark.slow

FIXTURES = os.path.join(REPO, 'tests', 'fixtures')
APP_FIXTURE = os.path.join(FIXTURES, 'mros_v1_app')
MAKE_FRAGMENT = os.path.join(REPO, 'cmake', 'genmros.mk')
# genmros run from this checkout, the way make runs a command.
GENMROS_COMMAND = 'env PYTHONPATH=%s %s -m colcon_mros' % (REPO, sys.executable)


@pytest.fixture(scope='module')
def every_header_sources(debian_export, test_ws_export, tmp_path_factory):
    directory = tmp_path_factory.mktemp('every_header')
    sources = []
    for name, root in (('debian', debian_export), ('test_ws', test_ws_export)):
        source = str(directory / ('%s.cpp' % name))
        assert every_header_translation_unit(root, source) > (150 if name == 'debian' else 14)
        sources.append((source, root))
    return sources


@pytest.mark.parametrize('target', sorted(TARGETS))
@pytest.mark.parametrize('mode', LANGUAGE_MODES)
def test_every_header_compiles_without_warnings(every_header_sources, target, mode):
    for source, include_root in every_header_sources:
        command = TARGETS[target] + ['-std=' + mode] + STRICT_FLAGS + [
            '-fsyntax-only', '-I', include_root, source]
        result = subprocess.run(command, capture_output=True, text=True)
        assert result.returncode == 0, result.stderr[-4000:]
        # libstdc++'s ABI notes on ARM are notes; a warning would have failed above.
        assert 'warning:' not in result.stderr, result.stderr[-4000:]


def _snapshot(directory):
    return {os.path.relpath(p, directory): open(p, 'rb').read()
            for p in glob.glob(os.path.join(directory, '**', '*'), recursive=True)
            if os.path.isfile(p)}


@pytest.fixture
def app_dir(tmp_path):
    """The v1-style app, copied so its Makefile finds test_ws."""
    app = tmp_path / 'app'
    shutil.copytree(APP_FIXTURE, str(app))
    os.makedirs(str(app / 'include'))
    makefile = app / 'Makefile'
    makefile.write_text(makefile.read_text().replace('../../../test_ws/src',
                                                     os.path.join(TEST_WS, 'src')))
    return app


def _make(app, *arguments):
    return subprocess.run(['make', '-C', str(app), 'GENMROS=' + GENMROS_COMMAND,
                           'GENMROS_MK=' + MAKE_FRAGMENT] + list(arguments),
                          capture_output=True, text=True)


STORAGE_FLAGS = {'heap': '', 'bounded': '--storage bounded --options bounds.options'}


@pytest.mark.parametrize('storage', sorted(STORAGE_FLAGS))
def test_the_make_fragment_gives_an_app_its_headers_in_either_storage(app_dir, storage):
    made = _make(app_dir, 'MROS_MSG_FLAGS=' + STORAGE_FLAGS[storage])
    assert made.returncode == 0, made.stdout[-3000:] + made.stderr[-3000:]
    header = (app_dir / 'include' / 'mros_test' / 'PersonalData.h').read_text()
    assert ('mros::bounded_string<24> first_name;' if storage == 'bounded'
            else 'std::string first_name;') in header
    run = subprocess.run([str(app_dir / 'app')], capture_output=True, text=True)
    assert run.returncode == 0, run.stderr[-3000:]
    # 4 + 4 and 4 + 5 bytes for the two strings, 2 for the uint16, 4 for the int32.
    assert run.stdout.splitlines() == ['person 23 of 23 bytes: Phil Woods 83 1',
                                       'nested Zoot -5 2']


def test_make_regenerates_headers_when_a_definition_changes(app_dir, tmp_path):
    workspace = tmp_path / 'ws'
    shutil.copytree(os.path.join(TEST_WS, 'src'), str(workspace / 'src'))
    paths = 'MROS_MSG_PATHS=%s' % (workspace / 'src')
    made = _make(app_dir, paths)
    assert made.returncode == 0, made.stderr[-3000:]
    assert 'genmros: exported 13 message' in made.stdout
    # The fragment passes the source tree by its public option.
    assert 'the old name goes' not in made.stderr
    header = app_dir / 'include' / 'mros_test' / 'PersonalData.h'
    assert 'int32_t score;' in header.read_text()

    again = _make(app_dir, paths)
    assert again.stdout == "make: Entering directory '%s'\nmake: 'app' is up to date.\n" \
        "make: Leaving directory '%s'\n" % (app_dir, app_dir)

    # A setting is part of the run: another definition text makes the headers anew.
    compact = _make(app_dir, paths, 'MROS_MSG_DEFINITION_TEXT=compact')
    assert compact.returncode == 0, compact.stderr[-3000:]
    assert 'genmros: exported 13 message' in compact.stdout
    assert '(genmros mros-v1-export --definition-text compact)' in header.read_text()

    definition = workspace / 'src' / 'mros_test' / 'msg' / 'PersonalData.msg'
    definition.write_text(definition.read_text() + 'float64 height\n')
    changed = _make(app_dir, paths)
    assert changed.returncode == 0, changed.stderr[-3000:]
    assert 'double height;' in header.read_text()
    assert 'g++' in changed.stdout  # the app was rebuilt against the new header


def test_make_refuses_bad_input_and_leaves_the_include_dir(app_dir):
    made = _make(app_dir)
    assert made.returncode == 0, made.stderr[-3000:]
    before = _snapshot(str(app_dir / 'include'))

    unknown = _make(app_dir, 'MROS_MSG_TYPES=no_such_pkg/Thing')
    assert unknown.returncode != 0
    errors = [line for line in unknown.stderr.splitlines() if line.startswith('genmros: error:')]
    assert errors == ["genmros: error: unknown package 'no_such_pkg' for type 'no_such_pkg/Thing' "
                      '(not in the workspace or the installed ROS packages)']
    assert _snapshot(str(app_dir / 'include')) == before

    missing = _make(app_dir, 'GENMROS=/nonexistent/genmros', 'MROS_MSG_TYPES=mros_test/Empty')
    assert missing.returncode != 0
    assert "'/nonexistent/genmros' not found: install colcon-mros or set GENMROS" in missing.stderr
    assert _snapshot(str(app_dir / 'include')) == before

    nowhere = _make(app_dir, 'MROS_MSG_PATHS=/nonexistent/prefix')
    assert nowhere.returncode != 0
    assert ('genmros.mk: MROS_MSG_PATHS: /nonexistent/prefix: not a directory: a package path '
            'is a source tree of packages or an installed prefix (with share/<pkg>/msg)'
            in nowhere.stderr)
    assert _snapshot(str(app_dir / 'include')) == before


def test_the_make_fragment_stops_where_the_settings_are_too_small(app_dir, tmp_path):
    # The settings the app builds with, given to genmros in MROS_MSG_FLAGS:
    # the small settings with a subscriber header buffer too small for
    # PersonalData's even with the shortest names (NestedTypes, with its
    # 3.7 KB definition text, needs both buffers larger).
    made = _make(app_dir)
    assert made.returncode == 0, made.stderr[-3000:]
    before = _snapshot(str(app_dir / 'include'))
    usr_config, packet_config = header_paths(small_settings(
        tmp_path, MROS_PACKET_MAXSIZE_REQ_TCPROS=100, MROS_PACKET_MAXSIZE_RES_TCPROS=512))
    lines = {setting: define([packet_config], setting)[2]
             for setting in ('MROS_PACKET_MAXSIZE_REQ_TCPROS', 'MROS_PACKET_MAXSIZE_RES_TCPROS')}
    flags = 'MROS_MSG_FLAGS=--mros-v1-settings %s --mros-v1-settings %s' % (usr_config,
                                                                            packet_config)
    refused = _make(app_dir, flags)
    assert refused.returncode != 0
    misfits = re.findall(r'^genmros: error: (.+):(\d+): (\S+): '
                         r'.* needs (\w+) >= \d+ \(it is (\d+);',
                         refused.stderr, re.MULTILINE)
    assert sorted(misfits) == sorted(
        (str(packet_config), str(lines[setting]), type_name, setting, value)
        for type_name, setting, value in (
            ('mros_test/PersonalData', 'MROS_PACKET_MAXSIZE_REQ_TCPROS', '100'),
            ('mros_test/NestedTypes', 'MROS_PACKET_MAXSIZE_REQ_TCPROS', '100'),
            ('mros_test/NestedTypes', 'MROS_PACKET_MAXSIZE_RES_TCPROS', '512'))), refused.stderr
    assert refused.stderr.count('genmros: error:') == len(misfits)
    assert _snapshot(str(app_dir / 'include')) == before


def test_genmros_names_its_make_fragment():
    path = run_genmros('make-fragment').stdout.strip()
    assert os.path.isabs(path) and filecmp.cmp(path, MAKE_FRAGMENT, shallow=False)


def test_aggregates_cover_the_named_types_and_headers_their_closure(tmp_path):
    run_genmros('mros-v1-export', '--workspace', TEST_WS, '--type', 'mros_test/NestedTypes',
                '-o', str(tmp_path), *prefix_arguments(ros1_prefixes()))
    assert os.path.isfile(str(tmp_path / 'geometry_msgs' / 'Pose.h'))
    with open(str(tmp_path / 'message_class_specialization.h')) as stream:
        instantiations = [line for line in stream if line.startswith('template ')]
    assert instantiations == [
        'template ros::Subscriber ros::NodeHandle::subscribe(std::string, int, '
        'void (*)(mros_test::NestedTypes*));\n',
        'template ros::Publisher '
        'ros::NodeHandle::advertise<mros_test::NestedTypes>(std::string, int);\n',
        'template void ros::Publisher::publish(mros_test::NestedTypes&);\n']
    with open(str(tmp_path / 'message_headers.h')) as stream:
        cases = re.findall(r'case (\S+)::MROS_TYPE_ID', stream.read())
    assert cases == ['mros_test::NestedTypes', 'mros_test::NestedTypes']  # callCallback, getMD5Sum


def test_string_constants_cost_no_constructor_and_no_heap(test_ws_export, tmp_path):
    source = tmp_path / 'constants.cpp'
    source.write_text('#include <mros_test/Constants.h>\n'
                      'const char* greeting() { return mros_test::Constants::GREETING; }\n')
    objects = tmp_path / 'constants.o'
    command = TARGETS['cortex-m4'] + ['-std=gnu++98', '-Os'] + STRICT_FLAGS + [
        '-c', '-I', test_ws_export, '-o', str(objects), str(source)]
    subprocess.run(command, check=True)
    symbols = subprocess.run(['arm-none-eabi-nm', '-C', str(objects)], capture_output=True,
                             text=True, check=True).stdout
    assert 'GREETING' in symbols
    # No static constructor, no guard variable, no call into the allocator.
    for sign in ('_GLOBAL__sub_I', 'guard variable', 'operator new', 'malloc'):
        assert sign not in symbols, symbols
