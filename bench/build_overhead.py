#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""What genmros adds to a catkin or colcon build: build time with genmros
enabled divided by build time with it disabled (ROS_LANG_DISABLE=genmros),
measured side by side on two copies of the same workspace.

Two workspaces: test_ws as it is in the repository, and a synthetic one of
24 message packages (8 messages each, nesting std_msgs, geometry_msgs and
each other's types in a tree, so a build can run several at once).

For each build tool (catkin_make -j2, with make and with ninja; catkin build
-j2 -p2; colcon build --executor parallel --parallel-workers 2, with
--mros-export when enabled) and workspace: one copy built with genmros
enabled and one with it disabled, and --runs rounds of a clean build of each
(build, devel, install and log spaces removed), then --rebuilds no-change
rebuilds of each, the copies taking turns (a no-change rebuild takes
seconds, so single ones drown in the machine's noise). The table shows
medians of wall time and of CPU time (user + system of every process the
build ran; less sensitive to other load on the machine), and, for the
enabled builds, how many genmros processes the build started and the CPU
seconds they took (genmros runs through a wrapper that counts them). Last,
the start-up of genmros' catkin run: the modules it imports (python3 -X
importtime).

    /usr/bin/python3 bench/build_overhead.py [--runs 3] [--rebuilds 3]
        [--tools catkin_make,catkin_make_ninja,catkin_build,colcon] [--keep DIR]
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
sys.path.insert(0, REPO)  # the shared testing package

from testing.ros_paths import ros1_package_dir  # noqa: E402

TOOLS = ('catkin_make', 'catkin_make_ninja', 'catkin_build', 'colcon')
# Wraps genmros to count its processes and their CPU time (bash's times).
WRAPPER = '''#!/bin/bash
{genmros} "$@"
status=$?
{{ echo "run $1"; times; }} >> "$GENMROS_BENCH_LOG"
exit $status
'''
# What a clean build starts without.
BUILD_SPACES = ('build', 'devel', 'install', 'log', 'logs', 'mros_export')
SYNTHETIC_PACKAGES = 24
START_UP_RUNS = 7
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


def build_command(tool, workspace, wrapper, enabled):
    """The build command of tool, with genmros run through wrapper."""
    cmake_args = ['-DGENMROS_BIN=%s' % wrapper]
    if tool == 'catkin_make':
        return ['catkin_make', '-j2'] + cmake_args
    if tool == 'catkin_make_ninja':
        return ['catkin_make', '--use-ninja', '-j2'] + cmake_args
    if tool == 'catkin_build':
        return (['catkin', 'build', '-j2', '-p2', '--no-status', '--no-notify', '--cmake-args']
                + cmake_args)
    export = ['--mros-export', os.path.join(workspace, 'mros_export')] if enabled else []
    return (['colcon', 'build', '--executor', 'parallel', '--parallel-workers', '2'] + export
            + ['--cmake-args'] + cmake_args)


def genmros_runs(log):
    """(processes, CPU seconds) the wrapper logged."""
    runs, cpu = 0, 0.0
    if os.path.exists(log):
        with open(log) as stream:
            lines = stream.read().splitlines()
        for line in lines:
            if line.startswith('run '):
                runs += 1
            else:  # times: the shell's, then genmros' user and system time: "0m0.081s 0m0.012s"
                for field in line.split():
                    minutes, seconds = field.rstrip('s').split('m')
                    cpu += int(minutes) * 60 + float(seconds)
        os.remove(log)
    return runs, cpu


def timed_build(command, workspace, env):
    """(wall seconds, CPU seconds, genmros processes, their CPU seconds) of
    one build: command run in workspace with env, genmros (through WRAPPER)
    logging its runs into the workspace."""
    log = os.path.join(workspace, 'genmros-runs.log')
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.monotonic()
    result = subprocess.run(command, cwd=workspace, env=dict(env, GENMROS_BENCH_LOG=log),
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    wall = time.monotonic() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if result.returncode != 0:
        sys.exit('%s failed in %s:\n%s' % (' '.join(command), workspace, result.stdout[-4000:]))
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return (wall, cpu) + genmros_runs(log)


def measure(build, workspaces, runs, rebuilds, spaces):
    """{(enabled, 'clean'|'rebuild'): [build(enabled), ...]}: runs rounds of a
    clean build of each of workspaces ({enabled: the copy built that way},
    its spaces removed first), then rebuilds no-change rebuilds of each, the
    copies taking turns."""
    samples = {}
    for round_number in range(runs):
        order = (True, False) if round_number % 2 == 0 else (False, True)
        for enabled in order:
            for space in spaces:
                shutil.rmtree(os.path.join(workspaces[enabled], space), ignore_errors=True)
            samples.setdefault((enabled, 'clean'), []).append(build(enabled))
        for _ in range(rebuilds):
            for enabled in order:
                samples.setdefault((enabled, 'rebuild'), []).append(build(enabled))
    return samples


def measure_tool(tool, workspaces, runs, rebuilds, wrapper):
    """measure() of builds of workspaces with tool, genmros run through wrapper."""
    if tool == 'catkin_build':
        for workspace in workspaces.values():
            subprocess.run(['catkin', 'init'], cwd=workspace, check=True, capture_output=True)

    def build(enabled):
        workspace = workspaces[enabled]
        return timed_build(build_command(tool, workspace, wrapper, enabled), workspace,
                           build_environment(workspace, enabled))
    return measure(build, workspaces, runs, rebuilds, BUILD_SPACES)


def median(samples, column):
    return statistics.median(sample[column] for sample in samples)


def report_rows(tool, name, workspace, samples):
    rows = []
    for kind in ('clean', 'rebuild'):
        with_samples, without_samples = samples[(True, kind)], samples[(False, kind)]
        wall_with, wall_without = median(with_samples, 0), median(without_samples, 0)
        cpu_with, cpu_without = median(with_samples, 1), median(without_samples, 1)
        genmros_cpu = median(with_samples, 3)
        rows.append((tool, name, count_messages(workspace), kind,
                     '%.2f' % wall_without, '%.2f' % wall_with,
                     '%.2fx' % (wall_with / wall_without),
                     '%.2f' % cpu_with, '%.2fx' % (cpu_with / cpu_without),
                     '%d' % median(with_samples, 2), '%.2f' % genmros_cpu,
                     '%.1f%%' % (100.0 * genmros_cpu / cpu_with)))
    return rows


def print_table(rows):
    header = ('tool', 'workspace', 'msg+srv', 'build', 'without s', 'with s', 'wall ratio',
              'CPU with s', 'CPU ratio', 'genmros runs', 'genmros CPU s', 'genmros share')
    widths = [max(len(str(row[i])) for row in rows + [header]) for i in range(len(header))]
    for row in [header, tuple('-' * width for width in widths)] + rows:
        print('  '.join(str(cell).ljust(width) for cell, width in zip(row, widths)))


def print_start_up(workspace, genmros):
    """The modules the genmros program the builds ran imports in a catkin
    run, as -X importtime sees them."""
    package = os.path.join(workspace, 'src', 'bench_msgs_01')
    files = sorted(os.path.join(package, 'msg', name)
                   for name in os.listdir(os.path.join(package, 'msg')))
    scratch = os.path.join(workspace, 'start_up')
    include_flags = ['-I', 'bench_msgs_01:%s' % os.path.join(package, 'msg'),
                     '-I', 'bench_msgs_00:%s' % os.path.join(workspace,
                                                             'src', 'bench_msgs_00', 'msg'),
                     '-I', 'std_msgs:' + ros1_package_dir('std_msgs'),
                     '-I', 'geometry_msgs:' + ros1_package_dir('geometry_msgs')]
    commands = {
        'generator run (build, once per package; none at configure)': ['generate'] + files + [
            '-p', 'bench_msgs_01', '-o', os.path.join(scratch, 'bench_msgs_01'),
            '--all-of-package'] + include_flags,
    }
    print('\ngenmros start-up (python3 -X importtime, the median of %d runs; total import time '
          'and the largest imports):' % START_UP_RUNS)
    for name, arguments in commands.items():
        runs = sorted((_imports(genmros, arguments) for _ in range(START_UP_RUNS)),
                      key=lambda run: run[0])
        total, own, largest = runs[len(runs) // 2]
        print('  %s: %.1f ms of imports, %.1f ms of them colcon_mros\' own modules; %s'
              % (name, total / 1000.0, own / 1000.0, ', '.join(
                  '%s %.1f ms' % (module, cumulative / 1000.0)
                  for cumulative, module in largest)))


def _imports(genmros, arguments):
    """(all imports, colcon_mros' own, the five largest) of one genmros run, in µs."""
    result = subprocess.run(['/usr/bin/python3', '-X', 'importtime', genmros] + arguments,
                            capture_output=True, text=True, check=True)
    imports, own = [], 0
    for line in result.stderr.splitlines():
        fields = line.split('|')
        if line.startswith('import time:') and fields[1].strip().isdigit():
            imports.append((int(fields[1]), fields[2].rstrip()))
            if fields[2].strip().startswith('colcon_mros'):
                own += int(fields[0].split(':')[1])
    top_level = [(cumulative, module.strip()) for cumulative, module in imports
                 if not module.startswith('  ')]
    return (sum(cumulative for cumulative, _ in top_level), own,
            sorted(top_level, reverse=True)[:5])


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('--runs', type=int, default=3, help='rounds per workspace (default 3)')
    parser.add_argument('--rebuilds', type=int, default=3,
                        help='no-change rebuilds per round and setting (default 3)')
    parser.add_argument('--tools', default=','.join(TOOLS),
                        help='build tools, comma-separated (default: %(default)s)')
    parser.add_argument('--keep', metavar='DIR', help='build in DIR and keep it')
    options = parser.parse_args()
    root = options.keep or tempfile.mkdtemp(prefix='genmros-bench-')
    os.makedirs(root, exist_ok=True)
    wrapper = os.path.join(root, 'genmros-counted')
    genmros = shutil.which('genmros')
    with open(wrapper, 'w') as stream:
        stream.write(WRAPPER.format(genmros=genmros))
    os.chmod(wrapper, 0o755)
    try:
        rows = []
        for tool in options.tools.split(','):
            for name, make in (('test_ws', test_ws_copy), ('24 packages', synthetic_workspace)):
                directory = os.path.join(root, tool, name.replace(' ', '_'))
                workspaces = {enabled: make(os.path.join(directory, setting))
                              for enabled, setting in ((True, 'with'), (False, 'without'))}
                rows += report_rows(tool, name, workspaces[True], measure_tool(
                    tool, workspaces, options.runs, options.rebuilds, wrapper))
        print('Medians of %d clean builds and %d no-change rebuilds; "with" = genmros enabled '
              '(colcon: with --mros-export), "without" = ROS_LANG_DISABLE=genmros'
              % (options.runs, options.runs * options.rebuilds))
        print_table(rows)
        print_start_up(synthetic_workspace(os.path.join(root, 'start_up')), genmros)
    finally:
        if not options.keep:
            shutil.rmtree(root)


if __name__ == '__main__':
    main()
