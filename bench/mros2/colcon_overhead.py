#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""What the mros2 generator adds to a ROS 2 colcon build, side by side in one run.

    /usr/bin/python3 bench/mros2/colcon_overhead.py [--runs 2] [--rebuilds 6] [--repeats 5]

Three builds with Debian's colcon: test_ws_ros2 and ROS 2's test interface
files (Debian's ros2-test-interface-files: 12 messages, 3 services) as one
interface package, both with Debian's rosidl (rosidl_adapter and
rosidl_generator_cpp, nothing compiled); and test_ws_ros2 with the ROS 2
wheels' rosidl_default_generators (build/ros2-wheels: C, C++, Python and
their type support, compiled), as a ROS 2 distribution builds it. Each in
two copies: with the mros2 generator (find_package(rosidl_generator_mros2))
and without it (that line made find_package(rosidl_cmake), which on Debian,
where no rosidl_default_generators pulls it in, defines
rosidl_generate_interfaces()). Per workspace, --runs rounds of a clean
colcon build of each copy (build, install and log removed; the copies taking
turns), then --rebuilds no-change rebuilds of each; wall seconds and CPU
seconds (user + system of every process the build ran). The mros2 generator
runs through a wrapper (-Drosidl_generator_mros2_BIN) that counts its
processes and their CPU seconds, so a no-change rebuild shows whether it ran
at all.

Then, per interface package of the "with" copy: the commands that build ran
for rosidl_generator_cpp and for the mros2 generator (read from CMake's
build.make), each run --repeats times again on that build's arguments files,
alone, one after the other: the median CPU seconds of one process of each.
Both import rosidl_parser and build its grammar.
"""

import argparse
import glob
import os
import re
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.dirname(HERE))
from build_overhead import WRAPPER, measure, timed_build  # noqa: E402
from testing.ros_paths import KILTED_WHEELS, ros2_package_dir  # noqa: E402

TEST_WS_ROS2 = os.path.join(REPO, 'test_ws_ros2', 'src')
TEST_INTERFACE_FILES = os.path.dirname(ros2_package_dir('test_interface_files'))
MROS2_GENERATOR_LINE = re.compile(r'^\s*find_package\(rosidl_generator_mros2 REQUIRED\)\s*$',
                                  re.M)
INTERFACES_CMAKE = '''cmake_minimum_required(VERSION 3.16)
project(test_interfaces)
find_package(ament_cmake REQUIRED)
find_package(rosidl_generator_cpp REQUIRED)
find_package(rosidl_generator_mros2 REQUIRED)
rosidl_generate_interfaces(${{PROJECT_NAME}}
{files})
ament_package()
'''
INTERFACES_PACKAGE = '''<?xml version="1.0"?>
<package format="3">
  <name>test_interfaces</name>
  <version>0.0.1</version>
  <description>ROS 2's test interface files as one package, for the bench</description>
  <maintainer email="bench@colcon-mros.invalid">bench</maintainer>
  <license>Apache-2.0</license>
  <buildtool_depend>ament_cmake</buildtool_depend>
  <buildtool_depend>rosidl_generator_cpp</buildtool_depend>
  <member_of_group>rosidl_interface_packages</member_of_group>
  <export><build_type>ament_cmake</build_type></export>
</package>
'''
COLCON_BUILD = ['colcon', 'build', '--executor', 'parallel', '--parallel-workers', '2',
                '--cmake-args']
# What a clean build starts without.
COLCON_SPACES = ('build', 'install', 'log')
# The line of CMake's build.make that runs a generator over its arguments file.
GENERATOR_COMMAND = re.compile(r'^\t(\S.*--generator-arguments-file \S+.*)$', re.M)


def test_ws_ros2(root):
    shutil.copytree(TEST_WS_ROS2, os.path.join(root, 'src'))


def test_interfaces(root):
    package = os.path.join(root, 'src', 'test_interfaces')
    files = []
    for kind in ('msg', 'srv'):
        os.makedirs(os.path.join(package, kind))
        for path in sorted(glob.glob(os.path.join(TEST_INTERFACE_FILES, kind, '*.' + kind))):
            shutil.copy(path, os.path.join(package, kind))
            files.append('  "%s/%s"' % (kind, os.path.basename(path)))
    with open(os.path.join(package, 'CMakeLists.txt'), 'w') as stream:
        stream.write(INTERFACES_CMAKE.format(files='\n'.join(files)))
    with open(os.path.join(package, 'package.xml'), 'w') as stream:
        stream.write(INTERFACES_PACKAGE)


WHEELS = KILTED_WHEELS


def debian_environment(enabled):
    return dict(os.environ, PATH='/usr/bin:/bin')


def wheels_environment(enabled):
    """The wheels first; with the mros2 generator, /usr too, whose ament index
    registers it in rosidl's generator group (rosidl_default_generators)."""
    return dict(os.environ, PATH='%s/bin:/usr/bin:/bin' % WHEELS, CMAKE_PREFIX_PATH=WHEELS,
                AMENT_PREFIX_PATH=WHEELS + (':/usr' if enabled else ''))


WORKSPACES = (('test_ws_ros2, Debian\'s rosidl', test_ws_ros2, debian_environment),
              ("ROS 2's test interface files, one package, Debian's rosidl", test_interfaces,
               debian_environment),
              ("test_ws_ros2, the ROS 2 wheels' rosidl_default_generators", test_ws_ros2,
               wheels_environment))


def without_generator(root):
    """Take the mros2 generator out of every package of the workspace at root."""
    for path in glob.glob(os.path.join(root, 'src', '*', 'CMakeLists.txt')):
        with open(path) as stream:
            text = stream.read()
        with open(path, 'w') as stream:
            stream.write(MROS2_GENERATOR_LINE.sub('find_package(rosidl_cmake REQUIRED)', text))


def process_cpu(command, repeats, environment):
    """Median CPU seconds of one run of command (a shell line from build.make)."""
    seconds = []
    for _ in range(repeats):
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        subprocess.run(command, shell=True, check=True, stdout=subprocess.DEVNULL,
                       env=environment)
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        seconds.append((after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime))
    return statistics.median(seconds)


def generator_commands(workspace, package):
    """{'rosidl_generator_cpp'|'mros2': command} as the package's build ran them."""
    commands = {}
    for path in glob.glob(os.path.join(workspace, 'build', package, 'CMakeFiles', '*',
                                       'build.make')):
        with open(path) as stream:
            for command in GENERATOR_COMMAND.findall(stream.read()):
                key = 'mros2' if 'rosidl_generator_mros2__arguments' in command else (
                    'rosidl_generator_cpp' if 'rosidl_generator_cpp__arguments' in command
                    else None)
                if key:
                    commands[key] = command
    return commands


def median(samples, column):
    return statistics.median(sample[column] for sample in samples)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('--runs', type=int, default=2, help='clean builds of each copy')
    parser.add_argument('--rebuilds', type=int, default=6,
                        help='no-change rebuilds of each copy per round')
    parser.add_argument('--repeats', type=int, default=5,
                        help='runs of each generator command for its CPU time')
    options = parser.parse_args()
    rows, generators = [], []
    with tempfile.TemporaryDirectory(prefix='mros2_build_overhead_') as scratch:
        wrapper = os.path.join(scratch, 'rosidl_generator_mros2')
        with open(wrapper, 'w') as stream:
            stream.write(WRAPPER.format(genmros=shutil.which('rosidl_generator_mros2',
                                                             path='/usr/bin')))
        os.chmod(wrapper, 0o755)
        for number, (name, make, environment) in enumerate(WORKSPACES):
            if environment is wheels_environment and not os.path.isdir(WHEELS):
                print('no %s (scripts/setup.sh --tests): %s left out' % (WHEELS, name))
                continue
            copies = {}
            for enabled in (True, False):
                copies[enabled] = os.path.join(scratch, '%d-%s' % (number, enabled))
                make(copies[enabled])
                if not enabled:
                    without_generator(copies[enabled])
            command = COLCON_BUILD + ['-Drosidl_generator_mros2_BIN=%s' % wrapper]
            samples = measure(
                lambda enabled: timed_build(command, copies[enabled], environment(enabled)),
                copies, options.runs, options.rebuilds, COLCON_SPACES)
            for kind in ('clean', 'rebuild'):
                with_, without = samples[(True, kind)], samples[(False, kind)]
                rows.append('| %s, %s | %.2f s | %.2f s | %.3fx | %.2f s | %.2f s | %.3fx | '
                            '%d | %.2f s |' % (
                                name, 'clean build' if kind == 'clean' else 'no-change rebuild',
                                median(with_, 0), median(without, 0),
                                median(with_, 0) / median(without, 0),
                                median(with_, 1), median(without, 1),
                                median(with_, 1) / median(without, 1),
                                median(with_, 2), median(with_, 3)))
            for package in sorted(os.listdir(os.path.join(copies[True], 'build'))):
                commands = generator_commands(copies[True], package)
                if set(commands) == {'mros2', 'rosidl_generator_cpp'}:
                    cpp = process_cpu(commands['rosidl_generator_cpp'], options.repeats,
                                      environment(True))
                    ours = process_cpu(commands['mros2'], options.repeats, environment(True))
                    generators.append('| %s (%s) | %.3f s | %.3f s | %.2fx |'
                                      % (package, name.split(', ')[-1], cpp, ours, ours / cpp))
    print('colcon build with the mros2 generator against without it (medians of %d clean '
          'builds and %d no-change rebuilds of each; ratio: with / without)'
          % (options.runs, options.runs * options.rebuilds))
    print('| build | wall with | wall without | wall ratio | CPU with | CPU without | CPU ratio '
          '| mros2 generator processes | their CPU |')
    print('|---|---:|---:|---:|---:|---:|---:|---:|---:|')
    print('\n'.join(rows))
    print('\nOne generator process per interface package, on the same build\'s arguments files '
          '(median CPU of %d runs; ratio: mros2 / rosidl_generator_cpp)' % options.repeats)
    print('| package | rosidl_generator_cpp | mros2 generator | ratio |')
    print('|---|---:|---:|---:|')
    print('\n'.join(generators))


if __name__ == '__main__':
    main()
