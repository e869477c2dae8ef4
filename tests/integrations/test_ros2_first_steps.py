# SPDX-License-Identifier: BSD-3-Clause
"""The ROS 2 user's first steps (docs/mros2.md, "First steps"), as written.

- The docs' interface-package CMakeLists is test_ws_ros2's mros2_base_msgs
  file, which the colcon tests build on Debian 12 and test_rosidl_wheels.py
  with the wheels' rosidl.
- The message packages Debian 12 lacks come from the ROS 2 wheels in a venv
  (the one scripts/setup.sh --tests makes, from the pins the docs name):
  mros2-export reads them with --prefix; without it, the unknown package's
  line names the wheel.
- On ROS 2 Humble (opt-in: HUMBLE_ROSIDL_PREFIX, a prefix holding Humble's
  rosidl 3.1.6, rosidl_defaults and ament_cmake 1.3.11 built from their
  checkouts, with a setup.bash or setup.sh; docs/testing.md), test_ws_ros2
  builds with that rosidl (its CMake and its Python), sourced as a Humble
  user sources /opt/ros/humble, the generator's prefix not on
  AMENT_PREFIX_PATH, and gets its mros2 headers, equal to genmros' own. A
  package naming only rosidl_default_generators gets none there, and gets
  them once genmros' prefix is on AMENT_PREFIX_PATH.
"""

import os
import re
import shutil

import pytest

from support.checkout import REPO, run_genmros
from support.checkout_install import checkout_install
from support.build_integration import run, user_environment
from testing.ros_paths import KILTED_WHEELS

DOCS = os.path.join(REPO, 'docs', 'mros2.md')
INTERFACE_PACKAGE = os.path.join(REPO, 'test_ws_ros2', 'src', 'mros2_base_msgs')
WHEELS = KILTED_WHEELS
WHEEL_PINS = os.path.join(REPO, 'scripts', 'test-requirements-ros2-wheels.txt')
HUMBLE = os.environ.get('HUMBLE_ROSIDL_PREFIX', '')
# /opt/ros/humble has setup.bash; a prefix built by Debian 12's colcon (no
# colcon-bash) has the POSIX setup.sh, which bash sources the same way.
HUMBLE_SETUP = next((os.path.join(HUMBLE, name) for name in ('setup.bash', 'setup.sh')
                     if HUMBLE and os.path.isfile(os.path.join(HUMBLE, name))), None)


def _docs():
    with open(DOCS, encoding='utf-8') as stream:
        return stream.read()


def _section(text):
    start = text.index('## First steps')
    return text[start:text.index('\n## ', start + 1)]


def test_the_docs_cmakelists_is_the_one_the_tests_build():
    blocks = re.findall(r'```cmake\n(.*?)```', _section(_docs()), re.S)
    with open(os.path.join(INTERFACE_PACKAGE, 'CMakeLists.txt'), encoding='utf-8') as stream:
        assert blocks == [stream.read()]


def test_the_docs_wheels_are_the_pinned_ones():
    with open(WHEEL_PINS, encoding='utf-8') as stream:
        pins = set(re.findall(r'^(ros-[a-z-]+==[0-9.]+)$', stream.read(), re.M))
    named = set(re.findall(r'ros-[a-z-]+==[0-9.]+', _section(_docs())))
    assert named and named <= pins


@pytest.fixture(scope='module')
def wheels():
    if not os.path.isfile(os.path.join(WHEELS, 'bin', 'python')):
        pytest.fail('no %s: run scripts/setup.sh --tests' % WHEELS)
    return WHEELS


def test_a_firmware_takes_ros2_message_packages_from_the_wheels(wheels, tmp_path):
    result = run_genmros('mros2-export', '--prefix', wheels, '-o', str(tmp_path),
                         '--subscribe', 'cmd_vel:geometry_msgs/msg/Twist',
                         '--publish', 'image:sensor_msgs/msg/Image')
    assert 'genmros: 5 mros2 message types, 0 services' in result.stdout, result.stdout
    for header in ('geometry_msgs/msg/twist.hpp', 'geometry_msgs/msg/vector3.hpp',
                   'sensor_msgs/msg/image.hpp', 'std_msgs/msg/header.hpp',
                   'builtin_interfaces/msg/time.hpp'):
        assert (tmp_path / header).is_file(), header


def test_without_them_the_unknown_package_names_the_wheel(tmp_path):
    empty = tmp_path / 'empty_prefix'
    (empty / 'share').mkdir(parents=True)
    result = run_genmros('mros2-export', '--prefix', str(empty), '-o', str(tmp_path / 'out'),
                         '--subscribe', 'cmd_vel:geometry_msgs/msg/Twist', check=False)
    assert result.returncode == 1
    assert result.stderr == (
        "genmros: error: unknown package 'geometry_msgs' of type 'geometry_msgs/msg/Twist' (not "
        'in the workspace or the installed ROS 2 packages; AMENT_PREFIX_PATH or --prefix names '
        'the installed ones; where no ROS 2 distribution is installed, as on Debian 12, a venv '
        'with the wheel ros-geometry-msgs holds it: --prefix VENV, docs/mros2.md)\n')


def _humble_shell(tmp_path, **overrides):
    """A Humble user's shell: the distribution sourced (AMENT_PREFIX_PATH
    holds only it, unless overrides say otherwise), genmros installed
    elsewhere (this checkout's install). Returns (environment, command
    prefix sourcing the setup file)."""
    environment = user_environment(**dict({'AMENT_PREFIX_PATH': None}, **overrides))
    environment['PATH'] = '/usr/bin:' + environment['PATH']
    # Humble's rosidl 3.1 has no rosidl_pycommon (its helpers live in
    # rosidl_cmake); Debian's python3-rosidl 3.3.1, in /usr's dist-packages
    # on every sys.path here, has one. Hidden, as on a Humble machine, so the
    # generator takes Humble's rosidl_cmake.
    hidden = tmp_path / 'no_rosidl_pycommon'
    hidden.mkdir()
    (hidden / 'rosidl_pycommon.py').write_text(
        "raise ImportError('no rosidl_pycommon in ROS 2 Humble')\n")
    environment['PYTHONPATH'] = str(hidden) + os.pathsep + environment['PYTHONPATH']
    return environment, '. "%s" && ' % HUMBLE_SETUP


def _assert_humble_python(workspace, environment, source):
    """The rosidl Python modules that shell imports are the prefix's."""
    script = ('import rosidl_adapter, rosidl_parser\n'
              'from colcon_mros.ros2.rosidl import _helpers\n'
              'print(rosidl_adapter.__file__); print(rosidl_parser.__file__)\n'
              'print(_helpers().__file__)\n')
    result = run(['bash', '-c', source + 'exec python3 -W ignore -c "$0"', script], workspace,
                 environment)
    files = result.stdout.split()
    assert len(files) == 3 and files[2].endswith(
        os.path.join('rosidl_cmake', '__init__.py')), files
    for path in files:
        assert os.path.realpath(path).startswith(os.path.realpath(HUMBLE)), path


def _mros2_headers(workspace):
    """The installed files holding an mros2 header (the DDS type name)."""
    return [os.path.join(directory, name)
            for directory, _, names in os.walk(os.path.join(workspace, 'install'))
            for name in names
            if 'dds_::' in open(os.path.join(directory, name), errors='replace').read()]


def _assert_found_in_humble(workspace, package, names):
    with open(os.path.join(workspace, 'build', package, 'CMakeCache.txt')) as stream:
        cache = stream.read()
    for name in names:
        found = re.search(r'^%s_DIR:PATH=(.*)$' % name, cache, re.M).group(1)
        assert os.path.realpath(found).startswith(os.path.realpath(HUMBLE)), (name, found)


humble = pytest.mark.skipif(
    HUMBLE_SETUP is None,
    reason='needs ROS 2 Humble\'s rosidl built into a prefix (setup.bash or setup.sh): set '
           'HUMBLE_ROSIDL_PREFIX (docs/testing.md)')


@pytest.mark.slow
@humble
def test_humble_builds_the_docs_package_with_its_rosidl(tmp_path):
    workspace = str(tmp_path / 'ws')
    shutil.copytree(os.path.join(REPO, 'test_ws_ros2', 'src'), os.path.join(workspace, 'src'))
    environment, source = _humble_shell(tmp_path)
    _assert_humble_python(workspace, environment, source)
    run(['bash', '-c', source + 'exec colcon build --event-handlers console_direct+'],
        workspace, environment)
    _assert_found_in_humble(workspace, 'mros2_base_msgs',
                            ('rosidl_cmake', 'rosidl_default_generators', 'rosidl_generator_cpp'))
    expected = tmp_path / 'expected'
    run_genmros('mros2-export', '--workspace', os.path.join(REPO, 'test_ws_ros2'), '-o',
                str(expected), '--package', 'mros2_base_msgs', '--package', 'mros2_test_msgs')
    installed = _mros2_headers(workspace)
    for header in ('mros2_base_msgs/msg/stamp.hpp', 'mros2_test_msgs/msg/reading.hpp',
                   'mros2_test_msgs/srv/query.hpp'):
        # rosidl_generator_cpp's header has the same name: the mros2 one
        # carries the DDS type name.
        ours = [path for path in installed if path.endswith(os.sep + header)]
        assert len(ours) == 1, (header, ours)
        with open(ours[0]) as built, open(str(expected / header)) as exported:
            assert built.read() == exported.read(), header


DEFAULTS_ONLY_CMAKELISTS = """cmake_minimum_required(VERSION 3.16)
project(defaults_only_msgs)

find_package(ament_cmake REQUIRED)
find_package(rosidl_default_generators REQUIRED)

rosidl_generate_interfaces(${PROJECT_NAME}
  "msg/Stamp.msg")

ament_package()
"""


@pytest.mark.slow
@humble
@pytest.mark.parametrize('on_ament_prefix_path', [False, True], ids=['elsewhere', 'indexed'])
def test_humble_defaults_find_the_generator_only_through_the_ament_index(
        tmp_path, on_ament_prefix_path):
    # A package naming only rosidl_default_generators (no
    # find_package(rosidl_generator_mros2)): Humble's extras file
    # find_package()s the rosidl_generator_packages of the ament index under
    # AMENT_PREFIX_PATH, so the mros2 headers come only with genmros'
    # prefix there (design.md: the Humble trap, silent without it).
    package = tmp_path / 'ws' / 'src' / 'defaults_only_msgs'
    shutil.copytree(os.path.join(INTERFACE_PACKAGE, 'msg'), str(package / 'msg'))
    (package / 'CMakeLists.txt').write_text(DEFAULTS_ONLY_CMAKELISTS)
    with open(os.path.join(INTERFACE_PACKAGE, 'package.xml'), encoding='utf-8') as stream:
        manifest = stream.read().replace('mros2_base_msgs', 'defaults_only_msgs').replace(
            '  <buildtool_depend>rosidl_generator_mros2</buildtool_depend>\n', '').replace(
            'rosidl_generator_cpp</buildtool_depend>',
            'rosidl_default_generators</buildtool_depend>')
    (package / 'package.xml').write_text(manifest)
    workspace = str(tmp_path / 'ws')
    overrides = {'AMENT_PREFIX_PATH': checkout_install().prefix} if on_ament_prefix_path else {}
    environment, source = _humble_shell(tmp_path, **overrides)
    run(['bash', '-c', source + 'exec colcon build --event-handlers console_direct+'],
        workspace, environment)
    _assert_found_in_humble(workspace, 'defaults_only_msgs',
                            ('rosidl_default_generators', 'rosidl_generator_cpp'))
    installed = _mros2_headers(workspace)
    # Any file or directory the mros2 generator would have made.
    mros2_paths = [os.path.join(directory, name)
                   for directory, directories, files in os.walk(workspace)
                   for name in directories + files if 'mros2' in name]
    if not on_ament_prefix_path:
        assert installed == [] and mros2_paths == [], (installed, mros2_paths)
        return
    header = os.path.join(workspace, 'install', 'defaults_only_msgs', 'include',
                          'defaults_only_msgs', 'mros2', 'defaults_only_msgs', 'msg', 'stamp.hpp')
    assert installed == [header], installed
    expected = tmp_path / 'expected'
    run_genmros('mros2-export', '--workspace', workspace, '-o', str(expected),
                '--package', 'defaults_only_msgs')
    with open(header) as built, open(str(expected / 'defaults_only_msgs' / 'msg' /
                                         'stamp.hpp')) as exported:
        assert built.read() == exported.read()


# The user's rclpy node of the docs' last line: it publishes a Stamp once
# the graph shows its subscriber matched, and reads it back.
STAMP_NODE = '''
import rclpy
from rclpy.executors import SingleThreadedExecutor
from mros2_base_msgs.msg import Stamp

rclpy.init()
talker, listener = rclpy.create_node('talker'), rclpy.create_node('listener')
received = []
listener.create_subscription(Stamp, 'stamp', received.append, 10)
publisher = talker.create_publisher(Stamp, 'stamp', 10)
executor = SingleThreadedExecutor()
executor.add_node(talker)
executor.add_node(listener)
while publisher.get_subscription_count() == 0:
    executor.spin_once(timeout_sec=0.1)
publisher.publish(Stamp(sec=7, nanosec=8))
while not received:
    executor.spin_once(timeout_sec=0.1)
print('received sec=%d nanosec=%d' % (received[0].sec, received[0].nanosec))
rclpy.shutdown()
'''


def _own_package_lines():
    text = _docs()
    start = text.index('### Debian 12: your own interface package')
    block, = re.findall(r'```sh\n(.*?)```', text[start:text.index('\n## ', start)], re.S)
    return block


@pytest.mark.slow
def test_a_debian_users_own_package_reaches_rclpy_with_the_docs_lines(tmp_path):
    home = tmp_path / 'home'
    shutil.copytree(INTERFACE_PACKAGE, str(home / 'ws' / 'src' / 'mros2_base_msgs'))
    (home / 'ws' / 'my_node.py').write_text(STAMP_NODE)
    environment = user_environment(HOME=str(home), AMENT_PREFIX_PATH=None, ROS_DOMAIN_ID='77',
                                   ROS_AUTOMATIC_DISCOVERY_RANGE='LOCALHOST')
    result = run(['bash', '-e', '-c', _own_package_lines()], cwd=str(tmp_path), env=environment)
    # The generator was the checkout's (its prefix on CMAKE_PREFIX_PATH after
    # the venv), and the install holds the three kinds of output.
    cache = (home / 'ws' / 'build' / 'mros2_base_msgs' / 'CMakeCache.txt').read_text()
    assert 'rosidl_generator_mros2_DIR:PATH=%s' % os.path.join(
        checkout_install().prefix, 'share', 'rosidl_generator_mros2', 'cmake') in cache
    assert '_Python3_EXECUTABLE:INTERNAL=%s\n' % (home / 'ros2' / 'bin' / 'python3') in cache
    install = home / 'ws' / 'install' / 'mros2_base_msgs'
    for relative in ('include/mros2_base_msgs/mros2/mros2_base_msgs/msg/stamp.hpp',
                     'include/mros2_base_msgs/mros2_base_msgs/msg/stamp.hpp',
                     'lib/python3.11/site-packages/mros2_base_msgs/msg/_stamp.py'):
        assert (install / relative).is_file(), relative
    assert result.stdout.splitlines()[-1] == 'received sec=7 nanosec=8', result.stdout[-3000:]
