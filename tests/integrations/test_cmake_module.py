# SPDX-License-Identifier: BSD-3-Clause
"""cmake/mros_generate.cmake in a plain CMake firmware project
(tests/fixtures/build_integration/firmware), found with find_package(genmros)
as installed by the README's set-up.

mros_generate_messages() runs on a fresh copy of test_ws's message packages;
mros_import_messages() on the export dir of a catkin build (and of colcon in
test_colcon_export.py). The program prints PUB_MSG_MAX_SIZE, the type's MD5
sum and its serialized size; the MD5 sum is checked against genmsg's own.
"""

import os
import re
import shutil

import pytest
from support.settings_headers import header_paths, small_settings
from support.build_integration import (
    FIRMWARE_FIXTURE, TEST_WS_SRC, genmsg_md5, new_workspace, run, search_path_of, unwrapped)
from testing.ros_paths import ros1_package_dir, ros1_prefixes

# cmake, colcon, catkin or make builds: more than half a minute.
pytestmark = pytest.mark.slow

# What genmros itself gives a type with strings (--variable-size-budget).
VARIABLE_SIZE_BUDGET = 1024
REGENERATION_LOG_LINE = 'Generating mROS message headers for firmware'


class Firmware:
    """The fixture project configured in a build dir of its own."""

    def __init__(self, build_dir):
        self.build_dir = build_dir

    def configure(self, check=True, **cache):
        command = ['cmake', '-S', FIRMWARE_FIXTURE, '-B', self.build_dir]
        command += ['-D%s=%s' % (key, ';'.join(value) if isinstance(value, (list, tuple))
                                 else value) for key, value in sorted(cache.items())]
        return run(command, self.build_dir if os.path.isdir(self.build_dir) else '/',
                   check=check)

    def build(self):
        return run(['cmake', '--build', self.build_dir], self.build_dir).stdout

    def output(self):
        result = run([os.path.join(self.build_dir, 'firmware')], self.build_dir).stdout
        return dict(line.split('=', 1) for line in result.split())

    def aggregate(self, name):
        with open(os.path.join(self.build_dir, 'mros_messages', 'firmware', name)) as stream:
            return stream.read()


@pytest.fixture
def firmware(tmp_path):
    return Firmware(str(tmp_path / 'build'))


@pytest.fixture
def workspace(tmp_path):
    return new_workspace(str(tmp_path / 'ws'))


def test_generate_builds_the_firmware_from_msg_files(firmware, workspace):
    source = os.path.join(workspace, 'src')
    firmware.configure(MROS_PACKAGE_PATHS=[source] + ros1_prefixes())
    firmware.build()
    output = firmware.output()
    assert output['md5'] == genmsg_md5('mros_test/PersonalData', search_path_of(source))
    assert output['PUB_MSG_MAX_SIZE'] == str(VARIABLE_SIZE_BUDGET)
    # Four empty strings' lengths, uint16 age, int32 score.
    assert output['serialized'] == '14'


def test_generate_rebuilds_after_a_msg_change_and_not_otherwise(firmware, workspace):
    source = os.path.join(workspace, 'src')
    firmware.configure(MROS_PACKAGE_PATHS=[source] + ros1_prefixes())
    firmware.build()
    assert REGENERATION_LOG_LINE not in firmware.build()

    path = os.path.join(source, 'mros_test', 'msg', 'PersonalData.msg')
    with open(path, 'a') as stream:
        stream.write('float32 height_m\n')
    rebuilt = firmware.build()
    # The module passes the source tree and the prefixes by their public options.
    assert REGENERATION_LOG_LINE in rebuilt and 'the old name goes' not in rebuilt
    output = firmware.output()
    assert output['serialized'] == '18'
    assert output['md5'] == genmsg_md5('mros_test/PersonalData', search_path_of(source))


def test_generate_takes_installed_packages_from_the_ros_environment(firmware, workspace):
    # Only the source tree: geometry_msgs and std_msgs come from the ROS
    # environment (rospkg's: where nothing is sourced, Debian's /usr/share),
    # and a change there would regenerate the headers too.
    firmware.configure(MROS_PACKAGE_PATHS=os.path.join(workspace, 'src'),
                       FIRMWARE_TYPES='mros_test/NestedTypes')
    firmware.build()
    with open(firmware.build_dir + '/mros_messages/firmware.d') as stream:
        record = stream.read()
    pose = os.path.join(ros1_package_dir('geometry_msgs'), 'Pose.msg')
    for definition in (pose, os.path.join(ros1_package_dir('std_msgs'), 'Header.msg'),
                       os.path.join(workspace, 'src', 'mros_test', 'msg', 'NestedTypes.msg')):
        assert '\n%s:\n' % definition in record
    assert pose in _makefiles(firmware, 'build.make')


def _makefiles(firmware, name):
    """The text of every makefile called name that CMake wrote for the build."""
    text = ''
    for directory, _, names in os.walk(firmware.build_dir):
        if name in names:
            with open(os.path.join(directory, name)) as stream:
                text += stream.read()
    return text


def test_aggregates_hold_exactly_the_listed_types(firmware, workspace):
    firmware.configure(MROS_PACKAGE_PATHS=[os.path.join(workspace, 'src')] + ros1_prefixes(),
                       FIRMWARE_TYPES=['mros_test_base/Vector3i', 'std_msgs/ColorRGBA'])
    firmware.build()
    # Three int32 (12 bytes) and four float32 (16 bytes): both fixed-size.
    assert firmware.output()['PUB_MSG_MAX_SIZE'] == '16'
    headers = firmware.aggregate('message_headers.h')
    assert '#include <mros_test_base/Vector3i.h>' in headers
    assert '#include <std_msgs/ColorRGBA.h>' in headers
    # The two types, <cstddef>, the v1 delivery header and the fit check.
    assert headers.count('#include <') == 5 and '#include <mros_v1_delivery.h>' in headers
    assert '#include <mros_v1_fit_check.h>' in headers


def test_generate_fails_at_configure_time_for_an_unknown_type(firmware, workspace):
    result = firmware.configure(check=False, FIRMWARE_TYPES='mros_test/NoSuchType',
                                MROS_PACKAGE_PATHS=[os.path.join(workspace, 'src')]
                                + ros1_prefixes())
    assert result.returncode != 0
    assert "unknown type 'mros_test/NoSuchType'" in unwrapped(result.stdout)


def test_generate_fails_at_configure_time_for_a_missing_package(firmware, workspace):
    # mros_test needs mros_test_base, which is not on the search path.
    shutil.rmtree(os.path.join(workspace, 'src', 'mros_test_base'))
    result = firmware.configure(check=False, FIRMWARE_TYPES='mros_test/NestedTypes',
                                MROS_PACKAGE_PATHS=[os.path.join(workspace, 'src')]
                                + ros1_prefixes())
    assert result.returncode != 0
    assert "unknown package 'mros_test_base'" in unwrapped(result.stdout)


@pytest.fixture(scope='module')
def catkin_export(tmp_path_factory):
    """The export dir of a catkin_make build of test_ws's message packages."""
    workspace = new_workspace(str(tmp_path_factory.mktemp('export_ws')))
    export_dir = os.path.join(workspace, 'mros_export')
    run(['catkin_make', '-DMROS_EXPORT_DIR=%s' % export_dir], workspace)
    return export_dir


def test_import_builds_the_firmware_from_a_catkin_export(firmware, catkin_export):
    firmware.configure(MROS_MODE='import', MROS_EXPORT_DIR=catkin_export)
    firmware.build()
    output = firmware.output()
    assert output['md5'] == genmsg_md5('mros_test/PersonalData', search_path_of(TEST_WS_SRC))
    assert output['serialized'] == '14'
    # The headers come from the export dir; only the aggregates are the firmware's.
    generated = os.listdir(os.path.join(firmware.build_dir, 'mros_messages', 'firmware'))
    assert sorted(generated) == ['message_class_specialization.h', 'message_headers.h',
                                 'mros_v1_delivery.h', 'mros_v1_fit_check.h', 'msg_max_size.h']


def test_import_rebuilds_when_the_export_changes(firmware, catkin_export, tmp_path):
    export_dir = str(tmp_path / 'export')
    shutil.copytree(catkin_export, export_dir)
    firmware.configure(MROS_MODE='import', MROS_EXPORT_DIR=export_dir,
                       FIRMWARE_TYPES='mros_test_base/Vector3i')
    firmware.build()
    assert firmware.output()['PUB_MSG_MAX_SIZE'] == '12'
    assert REGENERATION_LOG_LINE not in firmware.build()
    # A re-export of a changed Vector3i (as the ROS build does it).
    copy = new_workspace(str(tmp_path / 'changed'))
    with open(os.path.join(copy, 'src', 'mros_test_base', 'msg', 'Vector3i.msg'), 'a') as stream:
        stream.write('int32 w\n')
    run(['genmros', 'generate', os.path.join(copy, 'src', 'mros_test_base', 'msg', 'Vector3i.msg'),
         '-p', 'mros_test_base', '-o', os.path.join(export_dir, 'include', 'mros_test_base')],
        copy)
    shutil.copy(os.path.join(copy, 'src', 'mros_test_base', 'msg', 'Vector3i.msg'),
                os.path.join(export_dir, 'share', 'mros_test_base', 'msg'))
    assert REGENERATION_LOG_LINE in firmware.build()
    assert firmware.output()['PUB_MSG_MAX_SIZE'] == '16'


def test_import_fails_at_configure_time_for_a_type_not_exported(firmware, catkin_export):
    result = firmware.configure(check=False, MROS_MODE='import', MROS_EXPORT_DIR=catkin_export,
                                FIRMWARE_TYPES='mros_test/NoSuchType')
    assert result.returncode != 0
    assert ("type 'mros_test/NoSuchType' is not in the export dir '%s'" % catkin_export
            in unwrapped(result.stdout))


def test_import_fails_at_configure_time_without_an_export(firmware, tmp_path):
    empty = str(tmp_path / 'empty')
    os.mkdir(empty)
    result = firmware.configure(check=False, MROS_MODE='import', MROS_EXPORT_DIR=empty)
    assert result.returncode != 0
    assert ("EXPORT_DIR '%s' holds no genmros export" % empty) in unwrapped(result.stdout)


def test_import_from_a_catkin_export_of_types_that_nest_installed_ones(firmware, catkin_export):
    # NestedTypes holds a std_msgs/Header and geometry_msgs types: the catkin
    # export carries their headers and definitions, so no ROS is needed here.
    for package in ('std_msgs', 'geometry_msgs'):
        assert os.path.isfile(os.path.join(catkin_export, 'share', package, 'package.xml'))
    assert os.path.isfile(os.path.join(catkin_export, 'include', 'std_msgs', 'Header.h'))
    firmware.configure(MROS_MODE='import', MROS_EXPORT_DIR=catkin_export,
                       FIRMWARE_TYPES='mros_test/NestedTypes')
    firmware.build()
    assert firmware.output()['md5'] == genmsg_md5(
        'mros_test/NestedTypes', search_path_of(TEST_WS_SRC))


CROSS_TOOLCHAIN = '''\
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_CXX_COMPILER arm-none-eabi-g++)
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)
set(CMAKE_FIND_ROOT_PATH "${CMAKE_CURRENT_LIST_DIR}/sysroot")
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
'''


def test_find_package_under_a_cross_toolchain_file(tmp_path):
    # A toolchain file that confines packages to its sysroot hides the host's
    # genmros; genmros_DIR=$(genmros cmake-dir) names it.
    (tmp_path / 'sysroot').mkdir()
    toolchain = tmp_path / 'toolchain.cmake'
    toolchain.write_text(CROSS_TOOLCHAIN)
    project = tmp_path / 'project'
    project.mkdir()
    (project / 'CMakeLists.txt').write_text(
        'cmake_minimum_required(VERSION 3.13)\nproject(firmware CXX)\n'
        'find_package(genmros REQUIRED)\n'
        'add_library(firmware STATIC firmware.cpp)\n'
        'mros_generate_messages(TARGET firmware TYPES mros_test/PersonalData PACKAGE_PATHS %s)\n'
        % TEST_WS_SRC)
    (project / 'firmware.cpp').write_text(
        '#include <message_headers.h>\n'
        'int size() { return mros_test::PersonalData().dataSize(); }\n')
    configure = ['cmake', '-S', str(project), '-DCMAKE_TOOLCHAIN_FILE=%s' % toolchain]
    hidden = run(configure + ['-B', str(tmp_path / 'plain')], str(tmp_path), check=False)
    assert hidden.returncode != 0 and 'genmrosConfig.cmake' in hidden.stdout
    cmake_dir = run(['genmros', 'cmake-dir'], str(tmp_path)).stdout.strip()
    run(configure + ['-B', str(tmp_path / 'named'), '-Dgenmros_DIR=%s' % cmake_dir], str(tmp_path))
    run(['cmake', '--build', str(tmp_path / 'named')], str(tmp_path))


PERSONAL_DATA_BOUNDS = 'mros_test/PersonalData.first_name max_size:%d\n* max_size:20\n'


def _bounds_file(tmp_path, first_name_bound):
    path = tmp_path / 'firmware.options'
    path.write_text(PERSONAL_DATA_BOUNDS % first_name_bound)
    return str(path)


def test_generate_bounded_storage_follows_its_options_file(firmware, workspace, tmp_path):
    options = _bounds_file(tmp_path, 10)
    firmware.configure(MROS_PACKAGE_PATHS=os.path.join(workspace, 'src'), MROS_STORAGE='bounded',
                       MROS_OPTIONS=options)
    firmware.build()
    # Exact: 4 + 10 and 4 + 20 for the strings, uint16 age, int32 score.
    assert firmware.output()['PUB_MSG_MAX_SIZE'] == '44'
    header = os.path.join(firmware.build_dir, 'mros_messages',
                          'firmware', 'mros_test', 'PersonalData.h')
    with open(header) as stream:
        assert 'mros::bounded_string<10> first_name;' in stream.read()
    _bounds_file(tmp_path, 30)
    assert REGENERATION_LOG_LINE in firmware.build()
    assert firmware.output()['PUB_MSG_MAX_SIZE'] == '64'


def test_import_bounded_storage_generates_its_own_headers(firmware, catkin_export, tmp_path):
    firmware.configure(MROS_MODE='import', MROS_EXPORT_DIR=catkin_export, MROS_STORAGE='bounded',
                       MROS_OPTIONS=_bounds_file(tmp_path, 10))
    firmware.build()
    assert firmware.output()['PUB_MSG_MAX_SIZE'] == '44'
    assert os.path.isfile(os.path.join(firmware.build_dir, 'mros_messages', 'firmware',
                                       'mros_test', 'PersonalData.h'))
    # The export's heap headers are not on the firmware's include path.
    flags = _makefiles(firmware, 'flags.make')
    assert 'mros_messages/firmware' in flags and os.path.join(
        catkin_export, 'include') not in flags


@pytest.mark.parametrize('cache, expected', [
    ({'MROS_STORAGE': 'stack'},
     "mros_generate_messages(): genmros mros-v1-export: error: argument "
     "--storage: invalid choice: 'stack' (choose from 'heap', 'bounded')"),
    ({'MROS_STORAGE': 'bounded', 'MROS_OPTIONS': '/nonexistent/firmware.options'},
     "mros_generate_messages(): genmros: error: /nonexistent/firmware.options: cannot read "
     'options file: No such file or directory'),
    ({'MROS_OPTIONS': '/nonexistent/firmware.options'},
     'mros_generate_messages(): genmros: error: --options sets bounds, which only --storage '
     'bounded uses'),
])
def test_bad_storage_arguments_fail_the_configure_step(firmware, workspace, cache, expected):
    result = firmware.configure(
        check=False, MROS_PACKAGE_PATHS=os.path.join(workspace, 'src'), **cache)
    assert result.returncode != 0
    assert expected in unwrapped(result.stdout)


def test_a_package_path_that_is_no_directory_fails_the_configure_step(firmware, workspace):
    result = firmware.configure(check=False, MROS_PACKAGE_PATHS=[os.path.join(workspace, 'src'),
                                                                 '/nonexistent/prefix'])
    assert result.returncode != 0
    assert ('mros_generate_messages(): PACKAGE_PATHS: /nonexistent/prefix: not a directory: a '
            'package path is a source tree of packages or an installed prefix (with '
            'share/<pkg>/msg)') in unwrapped(result.stdout)


def test_bad_options_line_fails_the_configure_step_with_its_place(firmware, workspace, tmp_path):
    options = tmp_path / 'firmware.options'
    options.write_text('mros_test/PersonalData.first_name max_size:ten\n')
    result = firmware.configure(check=False, MROS_PACKAGE_PATHS=os.path.join(workspace, 'src'),
                                MROS_STORAGE='bounded', MROS_OPTIONS=str(options))
    assert result.returncode != 0
    assert ("mros_generate_messages(): genmros: error: %s:1: max_size must be a positive integer, "
            "not 'ten'" % options) in unwrapped(result.stdout)


def _settings_headers(tmp_path, request_buffer):
    """Copies of the small mROS v1 settings headers (tests/fixtures/
    mros_v1_settings: the app's config, the library's packet config), with
    the subscriber header buffer set to request_buffer bytes."""
    return header_paths(small_settings(tmp_path, MROS_PACKET_MAXSIZE_REQ_TCPROS=request_buffer))


def _set_request_buffer(packet_config, size):
    text, count = re.subn(r'(#define MROS_PACKET_MAXSIZE_REQ_TCPROS\s+)\d+', r'\g<1>%d' % size,
                          packet_config.read_text())
    assert count == 1
    packet_config.write_text(text)


def test_the_fit_check_stops_configure_and_build_with_the_setting_to_change(firmware, workspace,
                                                                            tmp_path):
    settings = _settings_headers(tmp_path, 200)
    cache = dict(MROS_PACKAGE_PATHS=os.path.join(workspace, 'src'), MROS_V1_SETTINGS=settings)
    result = firmware.configure(check=False, **cache)
    assert result.returncode != 0
    misfit = re.search(r"mros_generate_messages\(\): genmros: error: (\S+):(\d+): "
                       r"mros_test/PersonalData: .* needs MROS_PACKET_MAXSIZE_REQ_TCPROS >= "
                       r"(\d+) \(it is 200; even with the shortest topic and caller id it "
                       r"needs (\d+)\)", unwrapped(result.stdout))
    assert misfit, result.stdout
    path, line = misfit.group(1), int(misfit.group(2))
    needed, certain = int(misfit.group(3)), int(misfit.group(4))
    assert path == settings[1]
    with open(path) as stream:
        assert stream.readlines()[line - 1].startswith('#define MROS_PACKET_MAXSIZE_REQ_TCPROS')
    # The value it asks for fits; what remains is the warning for the frame
    # of heap storage, which has no largest size.
    packet_config = tmp_path / 'mros_packet_config.h'
    _set_request_buffer(packet_config, needed)
    output = unwrapped(firmware.configure(**cache).stdout)
    assert 'connection header' not in output
    assert ('mros_generate_messages(): genmros: warning: mros_test/PersonalData: no largest '
            'frame (first_name (string) has no bound)') in output
    firmware.build()
    assert firmware.output()['serialized'] == '14'
    # The settings header is an input: a build after an edit checks again.
    # One byte less fits shorter names only, a warning; below the certain
    # need the build stops.
    _set_request_buffer(packet_config, needed - 1)
    output = unwrapped(firmware.build())
    assert REGENERATION_LOG_LINE in output
    assert 'warning: mros_test/PersonalData: a ROS subscriber\'s connection header' in output
    _set_request_buffer(packet_config, certain - 1)
    result = run(['cmake', '--build', firmware.build_dir], firmware.build_dir, check=False)
    assert result.returncode != 0
    assert 'needs MROS_PACKET_MAXSIZE_REQ_TCPROS >= %d (it is %d;' % (needed, certain - 1) \
        in unwrapped(result.stdout)
