# SPDX-License-Identifier: BSD-3-Clause
"""The mros2 generator changes nothing for the ordinary C++ code of an
interface package's users. An interface package names it before or after
rosidl's own generators (both are valid CMake); a consumer package then
builds, as rclcpp code does, against ${<pkg>_TARGETS} and through
ament_target_dependencies(), and gets rosidl_generator_cpp's headers
alone, while a firmware target that names the mros2 target gets the mros2
headers. A type the generator cannot carry (a wchar), and a type that holds
it, are skipped with one line each, and the package builds. With Debian's
rosidl (rosidl_generator_cpp) and with the ROS 2 wheels'
(rosidl_default_generators)."""

import json
import os
import re
import subprocess

import pytest

from support.file_trees import write_tree
from support.rosidl_wheels import build_interface_package, require_venv
from testing.ros_paths import KILTED_WHEELS

pytestmark = pytest.mark.slow

# What each rosidl offers an interface package for C++: Debian 12 has
# rosidl_generator_cpp alone; a ROS 2 distribution and its wheels have
# rosidl_default_generators.
ROSIDL_GENERATORS = {'debian': 'rosidl_generator_cpp', 'wheels': 'rosidl_default_generators'}
# Where each rosidl is: Debian's in /usr, the wheels' in their venv.
VENVS = {'debian': None, 'wheels': KILTED_WHEELS}
INTERFACE_CMAKE = '''cmake_minimum_required(VERSION 3.16)
project(spot_msgs)
find_package(ament_cmake REQUIRED)
find_package(%s REQUIRED)
find_package(%s REQUIRED)
rosidl_generate_interfaces(${PROJECT_NAME} "msg/Spot.msg" "msg/Wide.idl" "msg/Marks.msg")
ament_package()
'''
INTERFACE_PACKAGE = '''<?xml version="1.0"?>
<package format="3">
  <name>spot_msgs</name>
  <version>0.0.1</version>
  <description>An interface package as a user writes one</description>
  <maintainer email="maintainer@example.com">Maintainer</maintainer>
  <license>BSD-3-Clause</license>
  <buildtool_depend>ament_cmake</buildtool_depend>
  <member_of_group>rosidl_interface_packages</member_of_group>
  <export><build_type>ament_cmake</build_type></export>
</package>
'''
# Valid IDL mros2 cannot carry, and a message that holds it.
WIDE_IDL = '''module spot_msgs {
  module msg {
    struct Wide {
      wchar letter;
    };
  };
};
'''
MARKS_MSG = 'Spot spot\nWide wide\n'
CONSUMER_CMAKE = '''cmake_minimum_required(VERSION 3.16)
project(spot_consumer CXX)
find_package(ament_cmake REQUIRED)
find_package(spot_msgs REQUIRED)
message(STATUS "spot_msgs_TARGETS: ${spot_msgs_TARGETS}")
add_executable(node_by_targets node.cpp)
target_link_libraries(node_by_targets ${spot_msgs_TARGETS})
add_executable(node_by_ament node.cpp)
ament_target_dependencies(node_by_ament spot_msgs)
add_executable(firmware_by_name firmware.cpp)
target_link_libraries(firmware_by_name spot_msgs::spot_msgs__rosidl_generator_mros2)
add_executable(firmware_by_variable firmware.cpp)
target_link_libraries(firmware_by_variable ${spot_msgs_TARGETS__rosidl_generator_mros2})
'''
# SharedPtr is a member only rosidl_generator_cpp's header has; Marks has
# no mros2 header at all.
NODE_CPP = '''#include <memory>
#include "spot_msgs/msg/marks.hpp"
#include "spot_msgs/msg/spot.hpp"
int main()
{
  spot_msgs::msg::Spot::SharedPtr spot = std::make_shared<spot_msgs::msg::Spot>();
  spot_msgs::msg::Marks marks;
  marks.spot = *spot;
  return static_cast<int>(marks.spot.x);
}
'''
# readFrom() is a member only the mros2 header has.
FIRMWARE_CPP = '''#include "spot_msgs/msg/spot.hpp"
int main()
{
  bool (spot_msgs::msg::Spot::*read)(mros2_wire::Reader&) = &spot_msgs::msg::Spot::readFrom;
  spot_msgs::msg::Spot spot;
  return read == nullptr ? 1 : static_cast<int>(spot.x);
}
'''
NODE_TARGETS = ('node_by_targets', 'node_by_ament')
FIRMWARE_TARGETS = ('firmware_by_name', 'firmware_by_variable')


def _run(argv, env):
    result = subprocess.run(argv, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            text=True)
    assert result.returncode == 0, ' '.join(argv) + '\n' + result.stdout[-6000:]
    return result.stdout


class Build:
    """The interface package and its consumer, built and installed."""

    def __init__(self, root, rosidl, mros2_first):
        venv = VENVS[rosidl]
        if venv is not None:
            require_venv(venv)
        finds = ['rosidl_generator_mros2', ROSIDL_GENERATORS[rosidl]]
        self.source = os.path.join(root, 'spot_msgs')
        write_tree(self.source, {
            'CMakeLists.txt': INTERFACE_CMAKE % tuple(finds if mros2_first else finds[::-1]),
            'package.xml': INTERFACE_PACKAGE,
            'msg/Spot.msg': 'float64 x\nfloat64 y\n',
            'msg/Wide.idl': WIDE_IDL,
            'msg/Marks.msg': MARKS_MSG,
        })
        interface = build_interface_package(self.source, os.path.join(root, 'interface'), venv)
        self.install, self.interface_log = interface.install, interface.log

        # The consumer sees what a user of that rosidl sees: the venv's first.
        env = {key: value for key, value in os.environ.items()
               if key not in ('AMENT_PREFIX_PATH', 'CMAKE_PREFIX_PATH', 'PYTHONPATH')}
        env['PATH'] = '/usr/bin:/bin'
        prefixes = [self.install]
        if venv is not None:
            env.update(PATH='%s:/usr/bin:/bin' % os.path.join(venv, 'bin'),
                       AMENT_PREFIX_PATH=venv)
            prefixes.insert(0, venv)
        consumer = os.path.join(root, 'spot_consumer')
        os.makedirs(consumer)
        for name, text in (('CMakeLists.txt', CONSUMER_CMAKE), ('node.cpp', NODE_CPP),
                           ('firmware.cpp', FIRMWARE_CPP)):
            with open(os.path.join(consumer, name), 'w') as stream:
                stream.write(text)
        self.consumer_build = os.path.join(root, 'consumer_build')
        self.consumer_configure = _run(
            ['cmake', '-S', consumer, '-B', self.consumer_build,
             '-DCMAKE_PREFIX_PATH=%s' % ';'.join(prefixes),
             '-DCMAKE_EXPORT_COMPILE_COMMANDS=ON'], env)
        _run(['cmake', '--build', self.consumer_build, '-j2'], env)

    def include_dirs(self, target):
        """The -I and -isystem directories of target's compile command."""
        with open(os.path.join(self.consumer_build, 'compile_commands.json')) as stream:
            commands = json.load(stream)
        command, = [entry['command'] for entry in commands
                    if '/%s.dir/' % target in entry['command']]
        return re.findall(r'(?:-I|-isystem )(\S+)', command)

    def mros2_root(self):
        return os.path.join(self.install, 'include', 'spot_msgs', 'mros2')


@pytest.fixture(scope='module', params=[('debian', True), ('debian', False),
                                        ('wheels', True), ('wheels', False)],
                ids=['debian-mros2-first', 'debian-mros2-last',
                     'wheels-mros2-first', 'wheels-mros2-last'])
def build(request, tmp_path_factory):
    rosidl, mros2_first = request.param
    return Build(str(tmp_path_factory.mktemp('consumers')), rosidl, mros2_first)


def test_the_mros2_target_is_not_among_the_packages_targets(build):
    targets, = [line for line in build.consumer_configure.splitlines()
                if line.startswith('-- spot_msgs_TARGETS: ')]
    assert 'spot_msgs::spot_msgs__rosidl_generator_cpp' in targets.split(': ')[1].split(';')
    assert 'mros2' not in targets


def test_ordinary_code_compiles_against_rosidls_header_alone(build):
    # Both consumers compiled (SharedPtr is rosidl_generator_cpp's); the
    # mros2 include root is not on their path either, in either order.
    for target in NODE_TARGETS:
        assert os.access(os.path.join(build.consumer_build, target), os.X_OK)
        assert not [d for d in build.include_dirs(target) if 'mros2' in d], target


def test_a_target_that_names_the_mros2_target_gets_the_mros2_header(build):
    # readFrom() is the mros2 header's; its include root and the generator's
    # support headers are on the path.
    for target in FIRMWARE_TARGETS:
        assert os.access(os.path.join(build.consumer_build, target), os.X_OK)
        directories = build.include_dirs(target)
        assert build.mros2_root() in directories, directories
        assert any(d.endswith(os.path.join('include', 'rosidl_generator_mros2'))
                   for d in directories), directories


def test_a_type_mros2_cannot_carry_and_its_holder_are_skipped_with_one_line_each(build):
    wide = os.path.join(build.source, 'msg', 'Wide.idl')
    notices = sorted(line for line in build.interface_log.splitlines()
                     if line.startswith('rosidl_generator_mros2: '))
    assert notices == [
        'rosidl_generator_mros2: skipped spot_msgs/msg/Marks: it holds spot_msgs/msg/Wide, which '
        "mros2 cannot carry: %s:4: member 'letter': wchar has no agreed CDR size between ROS 2 "
        'serializers' % wide,
        'rosidl_generator_mros2: skipped spot_msgs/msg/Wide: mros2 cannot carry it: '
        "%s:4: member 'letter': wchar has no agreed CDR size between ROS 2 serializers" % wide,
    ]
    installed = sorted(os.path.relpath(os.path.join(d, name), build.mros2_root())
                       for d, _, names in os.walk(build.mros2_root()) for name in names)
    assert installed == ['spot_msgs/msg/spot.hpp']
    marker = os.path.join(build.install, 'share', 'ament_index', 'resource_index',
                          'rosidl_generator_mros2__packages', 'spot_msgs')
    with open(marker) as stream:
        assert stream.read() == 'spot_msgs/msg/spot.hpp\n'
    # rosidl's own C++ headers have every type.
    for header in ('spot.hpp', 'wide.hpp', 'marks.hpp'):
        assert os.path.isfile(os.path.join(build.install, 'include', 'spot_msgs', 'spot_msgs',
                                           'msg', header))
