#!/usr/bin/python3
"""What genmros adds to a catkin build: build time with genmros enabled
divided by build time with it disabled (ROS_LANG_DISABLE=genmros), measured
side by side on the same workspace.

Two workspaces: test_ws as it is in the repository, and a synthetic one of
24 message packages (8 messages each, nesting std_msgs, geometry_msgs and
each other's types in a tree, so catkin can build several at once).

For each, --runs rounds of: a clean `catkin_make -j2` (build/ and devel/
removed) and a no-change rebuild, once enabled and once disabled, in
alternating order. The table shows medians of wall time and of CPU time
(user + system of every process the build ran; less sensitive to other load
on the machine), and how many genmros runs the no-change rebuild made.

    /usr/bin/python3 bench/build_overhead.py [--runs 3] [--keep DIR]
"""

import argparse
import os
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
GENERATOR_LOG_LINE = 'Generating mROS headers from'
SYNTHETIC_PACKAGES = 24
SYNTHETIC_MESSAGES = 8

PACKAGE_XML = '''<?xml version="1.0"?>
<package format="2">
  <name>{name}</name>
  <version>0.0.1</version>
  <description>Synthetic message package for bench/build_overhead.py.</description>
  <maintainer email="bench@colcon-mros.invalid">bench</maintainer>
  <license>BSD</license>
  <buildtool_depend>catkin</buildtool_depend>
  <build_depend>message_generation</build_depend>
  <exec_depend>message_runtime</exec_depend>
{depends}</package>
'''

CMAKE_LISTS = '''cmake_minimum_required(VERSION 3.0.2)
project({name})
find_package(catkin REQUIRED COMPONENTS message_generation {deps})
add_message_files(DIRECTORY msg)
generate_messages(DEPENDENCIES {deps})
catkin_package(CATKIN_DEPENDS message_runtime {deps})
'''


def _message(index, parent):
    """One message: built-ins, strings, arrays, and nested types."""
    fields = ['Header header', 'uint32 count_%d' % index, 'float64[3] vector',
              'string label', 'int16[] samples', 'geometry_msgs/Pose pose',
              'geometry_msgs/Twist[] twists']
    if index > 0:
        fields.append('Sample%d previous' % (index - 1))
    if parent:
        fields.append('%s/Sample%d[] inherited' % (parent, index))
    return '\n'.join(fields) + '\n'


def synthetic_workspace(root):
    """SYNTHETIC_PACKAGES packages in a tree: package i nests package (i-1)//2."""
    for number in range(SYNTHETIC_PACKAGES):
        name = 'bench_msgs_%02d' % number
        parent = 'bench_msgs_%02d' % ((number - 1) // 2) if number else None
        deps = ['std_msgs', 'geometry_msgs'] + ([parent] if parent else [])
        package = os.path.join(root, 'src', name)
        os.makedirs(os.path.join(package, 'msg'))
        with open(os.path.join(package, 'package.xml'), 'w') as stream:
            stream.write(PACKAGE_XML.format(name=name, depends=''.join(
                '  <depend>%s</depend>\n' % dep for dep in deps)))
        with open(os.path.join(package, 'CMakeLists.txt'), 'w') as stream:
            stream.write(CMAKE_LISTS.format(name=name, deps=' '.join(deps)))
        for index in range(SYNTHETIC_MESSAGES):
            with open(os.path.join(package, 'msg', 'Sample%d.msg' % index), 'w') as stream:
                stream.write(_message(index, parent))
    return root


def test_ws_copy(root):
    shutil.copytree(os.path.join(REPO, 'test_ws', 'src'), os.path.join(root, 'src'))
    return root


def count_messages(workspace):
    return sum(1 for _, _, names in os.walk(os.path.join(workspace, 'src'))
               for name in names if name.endswith(('.msg', '.srv')))


def build_environment(workspace, genmros_enabled):
    env = {key: value for key, value in os.environ.items()
           if key not in ('ROS_LANG_DISABLE', 'MROS_EXPORT_DIR', 'CMAKE_PREFIX_PATH')}
    # Debian's catkin needs the Python that has catkin_pkg and genmsg.
    env['PATH'] = '/usr/local/bin:/usr/bin:/bin'
    env['PWD'] = workspace
    if not genmros_enabled:
        env['ROS_LANG_DISABLE'] = 'genmros'
    return env


def timed_build(workspace, env):
    """(wall seconds, CPU seconds, genmros runs) of one catkin_make."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.monotonic()
    result = subprocess.run(['catkin_make', '-j2'], cwd=workspace, env=env,
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    wall = time.monotonic() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if result.returncode != 0:
        sys.exit('catkin_make failed in %s:\n%s' % (workspace, result.stdout[-4000:]))
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return wall, cpu, result.stdout.count(GENERATOR_LOG_LINE)


def measure(workspace, runs):
    """{(enabled, 'clean'|'rebuild'): [(wall, cpu, generator runs), ...]}."""
    samples = {}
    for round_number in range(runs):
        order = (True, False) if round_number % 2 == 0 else (False, True)
        for enabled in order:
            env = build_environment(workspace, enabled)
            for space in ('build', 'devel'):
                shutil.rmtree(os.path.join(workspace, space), ignore_errors=True)
            samples.setdefault((enabled, 'clean'), []).append(timed_build(workspace, env))
            samples.setdefault((enabled, 'rebuild'), []).append(timed_build(workspace, env))
    return samples


def median(samples, column):
    return statistics.median(sample[column] for sample in samples)


def report_rows(name, workspace, samples):
    rows = []
    for kind in ('clean', 'rebuild'):
        with_samples, without_samples = samples[(True, kind)], samples[(False, kind)]
        wall_with, wall_without = median(with_samples, 0), median(without_samples, 0)
        cpu_with, cpu_without = median(with_samples, 1), median(without_samples, 1)
        rows.append((name, count_messages(workspace), kind,
                     '%.2f' % wall_without, '%.2f' % wall_with,
                     '%.2fx' % (wall_with / wall_without),
                     '%.2fx' % (cpu_with / cpu_without),
                     str(max(sample[2] for sample in with_samples))))
    return rows


def print_table(rows):
    header = ('workspace', 'msg+srv', 'build', 'without s', 'with s', 'wall ratio',
              'CPU ratio', 'genmros runs')
    widths = [max(len(str(row[i])) for row in rows + [header]) for i in range(len(header))]
    for row in [header, tuple('-' * width for width in widths)] + rows:
        print('  '.join(str(cell).ljust(width) for cell, width in zip(row, widths)))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('--runs', type=int, default=3, help='rounds per workspace (default 3)')
    parser.add_argument('--keep', metavar='DIR', help='build in DIR and keep it')
    options = parser.parse_args()
    root = options.keep or tempfile.mkdtemp(prefix='genmros-bench-')
    try:
        rows = []
        for name, make in (('test_ws', test_ws_copy), ('24 packages', synthetic_workspace)):
            workspace = make(os.path.join(root, name.replace(' ', '_')))
            rows += report_rows(name, workspace, measure(workspace, options.runs))
        print('catkin_make -j2, medians of %d runs; "with" = genmros enabled, '
              '"without" = ROS_LANG_DISABLE=genmros' % options.runs)
        print_table(rows)
    finally:
        if not options.keep:
            shutil.rmtree(root)


if __name__ == '__main__':
    main()
