# SPDX-License-Identifier: BSD-3-Clause
"""colcon build of ROS 2 interface packages with the rosidl_generator_mros2 extension.

A fresh copy of test_ws_ros2 (mros2_base_msgs, and mros2_test_msgs, whose
Reading contains mros2_base_msgs/Stamp) is built with colcon as a Debian 12
user builds it (--merge-install): /usr/bin first on PATH, no ROS variables
set. The packages find_package(rosidl_generator_cpp) and
find_package(rosidl_generator_mros2); this checkout's generator is used, not
an installed one: rosidl_generator_mros2_DIR names the CMake package of this
checkout's install (tests/support/checkout_install.py, which also holds the support
headers) and rosidl_generator_mros2_BIN a wrapper that runs the checkout's
entry point (and logs each run). Each package installs its headers under
include/<pkg>/mros2, no file twice, and exports a target an app links. The
steps share one workspace and run in file order; a package of its own shows
that exactly the listed interfaces get headers.
"""

import json
import os
import re
import shutil
import subprocess
import time

import pytest

from support.checkout import REPO
from support.checkout_install import checkout_install
from colcon_mros.integrations.rosidl_generator import (MARKER_RESOURCE, MROS2_INCLUDE_ROOT,
                                                       SUPPORT_INCLUDE_DIR)
from colcon_mros.mros2 import render
from testing.ros_paths import ros2_prefixes

# cmake and colcon builds.
pytestmark = pytest.mark.slow

TEST_WS_ROS2 = os.path.join(REPO, 'test_ws_ros2')
# The checkout as a prefix: what test_ament_index_discovery_finds_the_generator reads.
CHECKOUT_EXTENSION_DIR = os.path.join(REPO, 'share', 'rosidl_generator_mros2', 'cmake')
STRICT_CXX = ['g++', '-std=c++11', '-Wall', '-Wextra', '-Werror', '-pedantic', '-fsyntax-only']
# Variables of a sourced ROS environment the build must not see.
ROS_VARIABLES = ('AMENT_PREFIX_PATH', 'CMAKE_PREFIX_PATH', 'COLCON_PREFIX_PATH', 'PYTHONPATH',
                 'ROS_PACKAGE_PATH', 'ROS_DISTRO', 'ROS_VERSION', 'MROS_EXPORT_DIR')


class Workspace:
    def __init__(self, root):
        self.root = root
        shutil.copytree(os.path.join(TEST_WS_ROS2, 'src'), os.path.join(root, 'src'))
        self.install = os.path.join(root, 'install')
        self.generator_prefix = checkout_install().prefix
        self.extension_dir = os.path.join(self.generator_prefix, 'share',
                                          'rosidl_generator_mros2', 'cmake')
        self.support_include = os.path.join(self.generator_prefix, *SUPPORT_INCLUDE_DIR)
        self.genmros_log = os.path.join(root, 'genmros-runs.log')
        self.genmros = os.path.join(root, 'rosidl_generator_mros2')
        with open(self.genmros, 'w') as stream:
            stream.write('#!/bin/sh\necho "$*" >> "%s"\n'
                         'exec /usr/bin/python3 -m colcon_mros.integrations.rosidl_generator '
                         '"$@"\n'
                         % self.genmros_log)
        os.chmod(self.genmros, 0o755)
        self.env = {key: value for key, value in os.environ.items() if key not in ROS_VARIABLES}
        self.env['PATH'] = '/usr/bin:/bin:' + os.environ.get('PATH', '')
        self.env['PYTHONPATH'] = REPO

    def source(self, package, *parts):
        return os.path.join(self.root, 'src', package, *parts)

    def colcon_build(self, check=True):
        result = subprocess.run(
            ['colcon', 'build', '--merge-install', '--event-handlers', 'console_direct+',
             '--cmake-args', '-Drosidl_generator_mros2_BIN=%s' % self.genmros,
             '-Drosidl_generator_mros2_DIR=%s' % self.extension_dir],
            cwd=self.root, env=self.env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
            text=True)
        if check and result.returncode != 0:
            pytest.fail('colcon build failed (exit %d):\n%s'
                        % (result.returncode, result.stdout[-6000:]))
        return result

    def genmros_runs(self):
        """The generator's command lines the builds ran so far."""
        if not os.path.exists(self.genmros_log):
            return []
        with open(self.genmros_log) as stream:
            return stream.read().splitlines()

    def generator_runs(self):
        """The runs that generated headers."""
        return [run for run in self.genmros_runs()
                if run.startswith('--generator-arguments-file ')]

    def mros2_include(self, package):
        """The package's mros2 include root in the install."""
        return os.path.join(self.install, *MROS2_INCLUDE_ROOT) % package

    def mros2_header(self, relative):
        """An installed header, by its name below an include root (<pkg>/msg/<type>.hpp)."""
        package = relative.split(os.sep)[0]
        with open(os.path.join(self.mros2_include(package), relative)) as stream:
            return stream.read()

    def marker(self, package):
        """The generator's ament index marker of the package: its headers, one a line."""
        with open(os.path.join(self.install, 'share', 'ament_index', 'resource_index',
                               MARKER_RESOURCE, package)) as stream:
            return stream.read()

    def install_manifest(self, package):
        """The files the package's last install wrote (CMake's install_manifest.txt)."""
        with open(os.path.join(self.root, 'build', package, 'install_manifest.txt')) as stream:
            return stream.read().splitlines()

    def append(self, source_file, line):
        with open(source_file, 'a') as stream:
            stream.write(line + '\n')
        # These builds take well under a second: an edit in the same clock tick as the last
        # configure's stamp would look no newer than it (seen in full suite runs). A time a
        # second on is newer than anything the last build wrote.
        ahead = time.time_ns() + 1_000_000_000
        os.utime(source_file, ns=(ahead, ahead))


@pytest.fixture(scope='module')
def workspace(tmp_path_factory):
    workspace = Workspace(str(tmp_path_factory.mktemp('ros2_ws')))
    workspace.colcon_build()
    return workspace


def test_build_used_the_checkouts_generator(workspace):
    for package in ('mros2_base_msgs', 'mros2_test_msgs'):
        with open(os.path.join(workspace.root, 'build', package, 'CMakeCache.txt')) as stream:
            cache = stream.read()
        # -D without a type: the cache keeps them UNINITIALIZED.
        assert re.search(r'^rosidl_generator_mros2_DIR:\w+=%s$'
                         % re.escape(workspace.extension_dir), cache, re.M)
        assert re.search(r'^rosidl_generator_mros2_BIN:\w+=%s$' % re.escape(workspace.genmros),
                         cache, re.M)
    runs = workspace.generator_runs()
    assert len(runs) == 2, runs
    # rosidl's contract: one arguments file per package, as rosidl_generator_cpp's.
    with open(runs[1].split()[1]) as stream:
        arguments = json.load(stream)
    assert arguments['package_name'] == 'mros2_test_msgs'
    assert sorted(entry.rpartition(':')[2] for entry in arguments['idl_tuples']) == [
        'msg/Reading.idl', 'srv/Query.idl']
    assert workspace.source('mros2_test_msgs', 'msg', 'Reading.msg') in \
        arguments['ros_interface_files']
    # The types it contains from mros2_base_msgs: that package's installed .idl.
    assert 'mros2_base_msgs:%s' % os.path.join(workspace.install, 'share', 'mros2_base_msgs',
                                               'msg', 'Stamp.idl') \
        in arguments['ros_interface_dependencies']
    # The templates are dependencies of the rule, through the depfile the program writes.
    with open(os.path.join(workspace.root, 'build', 'mros2_test_msgs',
                           'rosidl_generator_mros2__mros2_test_msgs.stamp.d')) as stream:
        assert os.path.join(os.path.dirname(render.__file__), 'templates',
                            'message_class.hpp.em') in stream.read()


def _files_under(directory):
    return sorted(os.path.relpath(os.path.join(d, name), directory)
                  for d, _, names in os.walk(directory) for name in names)


def test_mros2_headers_are_installed_under_each_packages_include_root(workspace):
    assert _files_under(workspace.mros2_include('mros2_base_msgs')) == [
        os.path.join('mros2_base_msgs', 'msg', 'stamp.hpp')]
    assert _files_under(workspace.mros2_include('mros2_test_msgs')) == [
        os.path.join('mros2_test_msgs', 'msg', 'reading.hpp'),
        os.path.join('mros2_test_msgs', 'srv', 'query.hpp')]
    # No shared include root any more, and no support header in the workspace.
    assert not os.path.exists(os.path.join(workspace.install, 'include', 'mros2'))
    for directory, _, names in os.walk(workspace.install):
        assert not set(names) & set(render.support_headers()), directory


def test_no_file_is_installed_by_both_packages(workspace):
    base = workspace.install_manifest('mros2_base_msgs')
    test = workspace.install_manifest('mros2_test_msgs')
    assert os.path.join(workspace.mros2_include('mros2_base_msgs'), 'mros2_base_msgs', 'msg',
                        'stamp.hpp') in base
    assert set(base) & set(test) == set()


def test_each_package_has_the_generators_marker(workspace):
    index = os.path.join(workspace.install, 'share', 'ament_index', 'resource_index',
                         MARKER_RESOURCE)
    assert _files_under(index) == ['mros2_base_msgs', 'mros2_test_msgs']
    assert workspace.marker('mros2_test_msgs') == ('mros2_test_msgs/msg/reading.hpp\n'
                                                   'mros2_test_msgs/srv/query.hpp\n')


def test_the_support_headers_are_the_generators_once(workspace):
    assert _files_under(workspace.support_include) == sorted(render.support_headers())
    for name, text in render.support_headers().items():
        with open(os.path.join(workspace.support_include, name)) as stream:
            assert stream.read() == text, name


def test_message_header_declares_the_type_and_its_dds_name(workspace):
    header = workspace.mros2_header(os.path.join('mros2_test_msgs', 'msg', 'reading.hpp'))
    assert 'namespace mros2_test_msgs\n{\nnamespace msg\n{\n' in header
    assert 'class Reading ' in header
    assert '"mros2_test_msgs::msg::dds_::Reading_"' in header
    assert '#include "mros2_base_msgs/msg/stamp.hpp"' in header
    for member in ('mros2_base_msgs::msg::Stamp stamp;', 'mros::bounded_string<16> sensor;',
                   'std::array<float, 3> position{};', 'std::vector<int16_t> samples;',
                   'double scale = 1.5;', 'static constexpr uint8_t SENSOR_COUNT = 4u;'):
        assert member in header
    stamp = workspace.mros2_header(os.path.join('mros2_base_msgs', 'msg', 'stamp.hpp'))
    assert '"mros2_base_msgs::msg::dds_::Stamp_"' in stamp


def test_service_header_declares_both_halves(workspace):
    header = workspace.mros2_header(os.path.join('mros2_test_msgs', 'srv', 'query.hpp'))
    assert 'class Query_Request ' in header and 'class Query_Response ' in header
    assert '"mros2_test_msgs::srv::dds_::Query_Request_"' in header
    assert '"mros2_test_msgs::srv::dds_::Query_Response_"' in header
    assert '#include "mros2_test_msgs/msg/reading.hpp"' in header


def test_rosidls_own_cpp_headers_are_installed_too(workspace):
    for relative in (('mros2_test_msgs', 'mros2_test_msgs', 'msg', 'reading.hpp'),
                     ('mros2_test_msgs', 'mros2_test_msgs', 'srv', 'query.hpp'),
                     ('mros2_base_msgs', 'mros2_base_msgs', 'msg', 'stamp.hpp')):
        assert os.path.isfile(os.path.join(workspace.install, 'include', *relative)), relative


APP_SOURCE = '''#include "mros2_base_msgs/msg/stamp.hpp"
#include "mros2_test_msgs/msg/reading.hpp"
#include "mros2_test_msgs/srv/query.hpp"
int main()
{
  mros2_test_msgs::msg::Reading reading;
  mros2_base_msgs::msg::Stamp stamp;
  reading.stamp = stamp;
  reading.stamp.nanosec = 1u;
  return static_cast<int>(reading.samples.size());
}
'''
# An app of the installed packages, as a user writes one: the targets their
# packages export, nothing else named.
APP_CMAKE = '''cmake_minimum_required(VERSION 3.16)
project(app CXX)
find_package(mros2_base_msgs REQUIRED)
find_package(mros2_test_msgs REQUIRED)
add_executable(app app.cpp)
target_compile_options(app PRIVATE -Wall -Wextra -Werror -pedantic)
target_link_libraries(app PRIVATE
  mros2_base_msgs::mros2_base_msgs__rosidl_generator_mros2
  ${mros2_test_msgs_TARGETS__rosidl_generator_mros2})
message(STATUS "mros2 targets: ${mros2_test_msgs_TARGETS__rosidl_generator_mros2}")
'''


def test_installed_headers_compile_with_the_support_headers(workspace, tmp_path):
    source = str(tmp_path / 'use.cpp')
    with open(source, 'w') as stream:
        stream.write(APP_SOURCE)
    result = subprocess.run(STRICT_CXX + ['-I', workspace.mros2_include('mros2_test_msgs'),
                                          '-I', workspace.mros2_include('mros2_base_msgs'),
                                          '-I', workspace.support_include, source],
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    assert result.returncode == 0, result.stdout


def test_an_app_links_the_exported_targets_and_compiles(workspace, tmp_path):
    app = tmp_path / 'app'
    app.mkdir()
    (app / 'CMakeLists.txt').write_text(APP_CMAKE)
    (app / 'app.cpp').write_text(APP_SOURCE)
    build = str(tmp_path / 'build')
    env = dict(workspace.env, CMAKE_PREFIX_PATH=workspace.install)
    for command in (['cmake', '-S', str(app), '-B', build], ['cmake', '--build', build]):
        result = subprocess.run(command, env=env, stdout=subprocess.PIPE,
                                stderr=subprocess.STDOUT, text=True)
        assert result.returncode == 0, result.stdout[-6000:]
        if command[1] == '-S':
            assert '-- mros2 targets: mros2_test_msgs::mros2_test_msgs__rosidl_generator_mros2' \
                in result.stdout.splitlines()
    assert os.access(os.path.join(build, 'app'), os.X_OK)


def test_unchanged_rebuild_runs_no_genmros(workspace):
    before = len(workspace.genmros_runs())
    workspace.colcon_build()
    assert len(workspace.genmros_runs()) == before


def test_a_changed_generator_file_regenerates_every_package(workspace):
    """The depfile the generator writes names its own files: a template
    newer than the headers regenerates them (its time is put back after)."""
    template = os.path.join(os.path.dirname(render.__file__), 'templates',
                            'message_class.hpp.em')
    before = len(workspace.generator_runs())
    times = os.stat(template)
    os.utime(template, (times.st_atime, time.time() + 60))
    try:
        workspace.colcon_build()
    finally:
        os.utime(template, ns=(times.st_atime_ns, times.st_mtime_ns))
    assert len(workspace.generator_runs()) == before + 2


def test_edited_message_is_regenerated(workspace):
    before = len(workspace.generator_runs())
    workspace.append(workspace.source('mros2_test_msgs', 'msg', 'Reading.msg'),
                     'uint32 count  # added after the first build')
    workspace.colcon_build()
    header = workspace.mros2_header(os.path.join('mros2_test_msgs', 'msg', 'reading.hpp'))
    assert 'uint32_t count = 0u;' in header
    assert 'mros2_wire::write(writer, count);' in header
    assert len(workspace.generator_runs()) == before + 1, 'only mros2_test_msgs is regenerated'


def test_a_message_mros2_cannot_carry_is_skipped_with_its_holders_naming_the_file(workspace):
    # rosidl takes the bound (its C++ member is a std::string); an mros2
    # message image cannot be that long. The packages build, as with
    # rosidl_generator_cpp alone, without the mros2 headers of Stamp and of
    # Reading, which holds it. (A fixed array as long, e.g.
    # float64[600000000], takes genmros minutes: it sizes arrays element
    # by element.)
    stamp = workspace.source('mros2_base_msgs', 'msg', 'Stamp.msg')
    with open(stamp) as stream:
        original = stream.read()
    workspace.append(stamp, 'string<=5000000000 label')
    try:
        result = workspace.colcon_build()
        notices = [line for line in result.stdout.splitlines()
                   if line.startswith('rosidl_generator_mros2: skipped')]
        too_long = ('mros2_base_msgs/msg/Stamp can take 5000000013 bytes in CDR, more than the '
                    '4294967291 a message can have')
        # Another package's type, as rosidl passes it: its installed .idl.
        installed_stamp = os.path.join(workspace.install, 'share', 'mros2_base_msgs', 'msg',
                                       'Stamp.idl')
        assert notices == [
            'rosidl_generator_mros2: skipped mros2_base_msgs/msg/Stamp: mros2 cannot carry it: '
            '%s: %s' % (stamp, too_long),
            'rosidl_generator_mros2: skipped mros2_test_msgs/msg/Reading: it holds '
            'mros2_base_msgs/msg/Stamp, which mros2 cannot carry: %s: %s'
            % (installed_stamp, too_long),
            'rosidl_generator_mros2: skipped mros2_test_msgs/srv/Query: it holds '
            'mros2_base_msgs/msg/Stamp, which mros2 cannot carry: %s: %s'
            % (installed_stamp, too_long)], result.stdout[-6000:]
        # The headers of the earlier build are gone from the build tree, and
        # the markers list none (an install keeps what it had, as for any
        # file a package stops installing).
        for package in ('mros2_base_msgs', 'mros2_test_msgs'):
            assert _files_under(os.path.join(workspace.root, 'build', package,
                                             'rosidl_generator_mros2')) == []
            assert workspace.marker(package) == ''
    finally:
        with open(stamp, 'w') as stream:
            stream.write(original)
    workspace.colcon_build()
    assert os.path.isfile(os.path.join(workspace.mros2_include('mros2_base_msgs'),
                                       'mros2_base_msgs', 'msg', 'stamp.hpp'))


def test_message_rosidl_rejects_fails_the_build_with_rosidls_error(workspace):
    # rosidl_adapter reads the .msg when CMake configures, before any
    # generator runs: the error is rosidl's, naming the type and the line.
    workspace.append(workspace.source('mros2_test_msgs', 'msg', 'Reading.msg'), 'int32 Bad-name')
    result = workspace.colcon_build(check=False)
    assert result.returncode != 0
    assert "Error processing 'int32 Bad-name' of 'mros2_test_msgs/Reading'" in result.stdout, \
        result.stdout[-6000:]
    assert "'Bad-name' is an invalid field name" in result.stdout


def test_ament_index_discovery_finds_the_generator(workspace, tmp_path):
    # What ROS 2 Humble's rosidl_default_generators does in its extras file
    # (Iron and later: rosidl_core_generators): find_package() every
    # package of the ament index's rosidl_generator_packages group, found on
    # AMENT_PREFIX_PATH. The checkout is laid out as a prefix
    # (share/ament_index, share/rosidl_generator_mros2), as the installed
    # distribution is.
    project = tmp_path / 'discover'
    project.mkdir()
    (project / 'CMakeLists.txt').write_text(
        'cmake_minimum_required(VERSION 3.16)\n'
        'project(discover NONE)\n'
        'find_package(ament_cmake_core REQUIRED)\n'
        'ament_index_get_resources(_generators "rosidl_generator_packages")\n'
        'foreach(_generator ${_generators})\n'
        '  find_package(${_generator} QUIET)\n'
        'endforeach()\n'
        'message(STATUS "generators: ${_generators}")\n'
        'message(STATUS "extensions: ${AMENT_EXTENSIONS_rosidl_generate_idl_interfaces}")\n'
        'message(STATUS "mros2 dir: ${rosidl_generator_mros2_DIR}")\n')
    env = dict(workspace.env, AMENT_PREFIX_PATH=os.pathsep.join(
        [REPO] + ros2_prefixes()), CMAKE_PREFIX_PATH=REPO)
    result = subprocess.run(
        ['cmake', '-S', str(project), '-B', str(tmp_path / 'build'),
         '-Drosidl_generator_mros2_BIN=%s' % workspace.genmros],
        env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    assert result.returncode == 0, result.stdout
    lines = dict(line[3:].split(': ', 1) for line in result.stdout.splitlines()
                 if line.startswith('-- ') and ': ' in line)
    assert 'rosidl_generator_mros2' in lines['generators'].split(';')
    assert ('rosidl_generator_mros2:rosidl_generator_mros2_generate_interfaces.cmake'
            in lines['extensions'].split(';'))
    assert lines['mros2 dir'] == CHECKOUT_EXTENSION_DIR


def test_a_generator_without_its_support_headers_stops_the_configure(workspace, tmp_path):
    """The checkout's share/ as the CMake package: no include/rosidl_generator_mros2 beside it."""
    build = str(tmp_path / 'build')
    result = subprocess.run(
        ['cmake', '-S', workspace.source('mros2_base_msgs'), '-B', build,
         '-Drosidl_generator_mros2_DIR=%s' % CHECKOUT_EXTENSION_DIR,
         '-Drosidl_generator_mros2_BIN=%s' % workspace.genmros],
        env=workspace.env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    assert result.returncode != 0
    assert ('rosidl_generator_mros2: no support headers in %s; reinstall colcon-mros '
            '(scripts/setup.sh)' % os.path.join(REPO, 'include', 'rosidl_generator_mros2')) \
        in ' '.join(result.stdout.split()), result.stdout[-3000:]


LISTED_PACKAGE_CMAKE = '''cmake_minimum_required(VERSION 3.16)
project(mros2_listed_msgs)

find_package(ament_cmake REQUIRED)
find_package(rosidl_generator_cpp REQUIRED)
find_package(rosidl_generator_mros2 REQUIRED)

# A message the build writes, listed as a tuple of its base and its path.
file(WRITE "${CMAKE_CURRENT_BINARY_DIR}/made/msg/Made.msg" "int32 value\\n")
# Two of the package's three messages: Left.msg is not an interface.
rosidl_generate_interfaces(${PROJECT_NAME}
  "msg/First.msg" "msg/Second.msg" "${CMAKE_CURRENT_BINARY_DIR}/made:msg/Made.msg")

ament_package()
'''


@pytest.fixture(scope='module')
def listed_workspace(tmp_path_factory):
    """A workspace of one package that lists some of its .msg files and one
    the build writes."""
    workspace = Workspace(str(tmp_path_factory.mktemp('listed_ws')))
    shutil.rmtree(os.path.join(workspace.root, 'src'))
    package = os.path.join(workspace.root, 'src', 'mros2_listed_msgs')
    os.makedirs(os.path.join(package, 'msg'))
    with open(os.path.join(TEST_WS_ROS2, 'src', 'mros2_base_msgs', 'package.xml')) as stream:
        manifest = stream.read().replace('mros2_base_msgs', 'mros2_listed_msgs')
    for name, text in (('package.xml', manifest), ('CMakeLists.txt', LISTED_PACKAGE_CMAKE),
                       ('msg/First.msg', 'int32 first\n'), ('msg/Second.msg', 'string second\n'),
                       ('msg/Left.msg', 'float64 left\n')):
        with open(os.path.join(package, name), 'w') as stream:
            stream.write(text)
    workspace.colcon_build()
    return workspace


def _package_headers(workspace, package):
    directory = os.path.join(workspace.mros2_include(package), package)
    return sorted(os.path.relpath(os.path.join(d, name), directory)
                  for d, _, names in os.walk(directory) for name in names)


def test_a_package_gets_headers_for_exactly_the_files_it_lists(listed_workspace):
    headers = _package_headers(listed_workspace, 'mros2_listed_msgs')
    assert os.path.join('msg', 'first.hpp') in headers
    assert os.path.join('msg', 'second.hpp') in headers
    assert os.path.join('msg', 'left.hpp') not in headers


def test_a_message_the_build_writes_and_lists_gets_its_header(listed_workspace):
    assert _package_headers(listed_workspace, 'mros2_listed_msgs') == [
        os.path.join('msg', name) for name in ('first.hpp', 'made.hpp', 'second.hpp')]
    header = listed_workspace.mros2_header(os.path.join('mros2_listed_msgs', 'msg', 'made.hpp'))
    assert 'int32_t value = 0;' in header
