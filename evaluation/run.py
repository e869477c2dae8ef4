#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""The main job, end to end with real tools: a ROS build emits the mROS
headers, a firmware's CMake build uses them, and the firmware exchanges
messages with real ROS nodes. One line per step, then a PASS/FAIL table.

1. catkin_make of test_ws, genmros beside gencpp and genpy, writes the export
   dir (MROS_EXPORT_DIR); colcon build --mros-export writes the same headers.
2. evaluation/firmware (find_package(genmros), mros_import_messages()) is
   built on that export dir for 32-bit ARM Linux, Cortex-M0 and Cortex-M4.
3. The ARM Linux program runs under qemu-arm beside a real rosmaster and
   rospy and roscpp nodes (evaluation/board.py): the paper's PersonalData in
   both directions, and five test_ws types sent back byte for byte.
4. With MROS_V1_ROOT naming the user's mROS v1 checkout: the paper's
   evaluation on that library, in all five directions (evaluation/mros_v1.py).
5. In sync by construction: a field added to a message in the workspace
   reaches the firmware through catkin_make and the firmware's rebuild.
6. The same for ROS 2 and mros2 (evaluation/ros2.py): colcon build
   --mros-export of test_ws_ros2, a firmware with mros2_import_messages()
   for 32-bit ARM Linux and Cortex-M4F, the fit check's verdict, the ARM
   program under qemu-arm with real rclpy nodes, and a field added.

  run.py [--messages N] [--build-dir DIR] [--ros2-only]

Uses the installed genmros (scripts/run-evaluation.sh installs it). Exits 0
only if every step passed. --ros2-only runs step 6 alone, to try the ROS 2
part on another venv of ROS 2 wheels (GENMROS_ROS2_WHEELS: testing/ros_paths.py).
"""

import argparse
import filecmp
import os
import shutil
import subprocess
import sys
import tempfile
import time

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# testing/, what the tests, the benches and the main job share, is not installed:
# it comes from this repository, after the installed genmros; so do the test tools
# from PyPI it uses (rosbags, numpy: scripts/setup.sh --tests, build/test-python).
sys.path.append(REPO)
sys.path.append(os.path.join(REPO, 'build', 'test-python'))

from testing import mros2_posix, mros2_soak  # noqa: E402
from testing.ros_graph import PYTHON, CatkinWorkspace  # noqa: E402

import board  # noqa: E402
import mros_v1  # noqa: E402
import ros2  # noqa: E402

TEST_WS_SRC = os.path.join(REPO, 'test_ws', 'src')
NODES_PACKAGE = 'mros_test_nodes'
MESSAGE_PACKAGES = ('mros_test_base', 'mros_test')
TRANSPORT = ('frames carried between qemu-arm and the ROS graph by evaluation/board_bridge.py: '
             "a rospy node that relays the board's bytes unread, under the type names, MD5 sums "
             "and definition texts of the board's genmros headers")


def _first_line(error):
    return (str(error).strip() or type(error).__name__).splitlines()[0]


class Steps:
    """Runs steps, prints one line each, and keeps the rows of the table."""

    def __init__(self):
        self.rows = []

    def run(self, title, function, *arguments):
        """function(*arguments) returns (its result, a detail line); a
        Failure, RuntimeError or AssertionError fails the step. Returns the
        result, or None if the step failed."""
        started = time.monotonic()
        print('%s ...' % title, flush=True)
        try:
            result, detail = function(*arguments)
            problem = None
        except (board.Failure, RuntimeError, AssertionError, subprocess.CalledProcessError) \
                as error:
            result, detail, problem = None, '', _first_line(error)
        self.add(title, detail, problem, time.monotonic() - started)
        return result

    def add(self, title, detail, problem, seconds=None):
        self.rows.append((title, problem))
        timing = ' (%.0f s)' % seconds if seconds is not None else ''
        print('  %s%s: %s' % ('PASS' if problem is None else 'FAIL', timing,
                              detail if problem is None else problem), flush=True)

    def skip(self, title, reason):
        self.rows.append((title, 'not run: ' + reason))
        print('%s: FAIL, not run: %s' % (title, reason), flush=True)

    def passed(self):
        return all(problem is None for _, problem in self.rows)

    def table(self):
        width = max(len(title) for title, _ in self.rows)
        lines = ['%-*s  %s' % (width, title, 'PASS' if problem is None else 'FAIL: ' + problem)
                 for title, problem in self.rows]
        return '\n'.join(lines)


def catkin_build(root):
    shutil.copytree(TEST_WS_SRC, os.path.join(root, 'src'))
    workspace = CatkinWorkspace(root, NODES_PACKAGE).build(
        os.path.join(root, 'catkin_make.log'), '-DCMAKE_BUILD_TYPE=Release', '-j2')
    headers = _headers(workspace.mros_export)
    if not os.path.isfile(os.path.join(workspace.mros_export, 'mros_export.cmake')) \
            or 'mros_test/PersonalData.h' not in headers:
        raise board.Failure('no export in %s' % workspace.mros_export)
    return workspace, 'export dir %s: %d headers, mros_export.cmake' % (
        workspace.mros_export, len(headers))


def _headers(export_dir):
    include = os.path.join(export_dir, 'include')
    return sorted(os.path.relpath(os.path.join(directory, name), include)
                  for directory, _, names in os.walk(include) for name in names)


def colcon_export(root, catkin_export):
    """colcon build --mros-export of test_ws's message packages; its headers
    must equal catkin's."""
    shutil.copytree(TEST_WS_SRC, os.path.join(root, 'src'))
    export_dir = os.path.join(root, 'mros_export')
    environment = dict(os.environ, PATH='/usr/bin:' + os.environ.get('PATH', ''))
    board.run_logged(['colcon', 'build', '--packages-up-to', *MESSAGE_PACKAGES,
                      '--mros-export', export_dir,
                      '--cmake-args', '-DPYTHON_EXECUTABLE=' + PYTHON],
                     os.path.join(root, 'colcon_build.log'), cwd=root, env=environment)
    catkin_headers, colcon_headers = _headers(catkin_export), _headers(export_dir)
    ours = [path for path in colcon_headers if path.split('/')[0] in MESSAGE_PACKAGES]
    missing = sorted(set(catkin_headers) - set(colcon_headers)) + sorted(
        set(ours) - set(catkin_headers))
    if missing:
        raise board.Failure('in one export only: %s' % ', '.join(missing[:5]))
    _, differing, errors = filecmp.cmpfiles(os.path.join(catkin_export, 'include'),
                                            os.path.join(export_dir, 'include'), catkin_headers,
                                            shallow=False)
    if differing or errors:
        raise board.Failure('headers differ from catkin\'s: %s' % ', '.join(differing + errors))
    return export_dir, ("%d headers, every one of catkin's export byte for byte (colcon also "
                        'exports %d more headers, of the installed packages they depend on)'
                        % (len(catkin_headers), len(colcon_headers) - len(catkin_headers)))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('--messages', type=int, default=5,
                        help='messages each receiver of the paper\'s directions must get '
                             '(default 5)')
    parser.add_argument('--build-dir', help='keep the builds here, in a new or empty directory '
                        '(default: a temporary one)')
    parser.add_argument('--ros2-only', action='store_true',
                        help='run the ROS 2 part alone (step 6)')
    args = parser.parse_args()
    mros_root = os.environ.get('MROS_V1_ROOT', '')
    steps = Steps()
    with tempfile.TemporaryDirectory(prefix='mros_main_job_') as scratch:
        build_root = os.path.abspath(args.build_dir or scratch)
        os.makedirs(build_root, exist_ok=True)
        if os.listdir(build_root):
            parser.error('--build-dir %s is not empty' % build_root)
        if args.ros2_only:
            run_ros2(steps, os.path.join(build_root, 'ros2'))
            return finish(steps)
        workspace = steps.run('catkin_make of test_ws (genmros beside gencpp and genpy)',
                              catkin_build, os.path.join(build_root, 'catkin_ws'))
        if workspace is None:
            return finish(steps)
        steps.run('colcon build --mros-export of the same packages', colcon_export,
                  os.path.join(build_root, 'colcon_ws'), workspace.mros_export)
        programs = {}
        for target in board.TARGETS:
            programs[target.name] = steps.run(
                'firmware (CMake, mros_import_messages) for %s' % target.title,
                board.build_firmware, workspace.mros_export,
                os.path.join(build_root, 'firmware', target.name), target)
        linux = programs['arm-linux-gnueabihf']
        if linux is None:
            steps.skip('the board under qemu-arm with ROS nodes', 'its firmware did not build')
        else:
            print('the board under qemu-arm with a rosmaster, rospy and roscpp nodes; %s ...'
                  % TRANSPORT, flush=True)
            try:
                for check in board.exchange(workspace, linux, args.messages):
                    steps.add(check.title, check.detail, check.problem)
            except (AssertionError, RuntimeError, OSError) as error:
                steps.add('the board under qemu-arm with ROS nodes', '', _first_line(error))
        if mros_v1.checkout_found(mros_root):
            run_mros_v1(steps, workspace, mros_root, os.path.join(build_root, 'mros_v1'),
                        args.messages)
        if linux is not None:
            steps.run('in sync by construction: a field added, catkin_make, firmware rebuilt',
                      lambda: (None, board.in_sync(
                          workspace, os.path.join(build_root, 'firmware', 'arm-linux-gnueabihf'),
                          linux, os.path.join(build_root, 'in_sync.log'))))
        run_ros2(steps, os.path.join(build_root, 'ros2'))
    if not mros_v1.checkout_found(mros_root):
        print("\nthe paper's evaluation on your mROS v1 library was not run: %s. Set "
              'MROS_V1_ROOT=<your checkout of mROS-base/mROS> to run it as well.'
              % ("MROS_V1_ROOT is not set" if not mros_root
                 else 'no mROS v1 checkout at %s (no mros-lib/Makefile.m)' % mros_root))
    return finish(steps)


def run_ros2(steps, build_root):
    """The ROS 2 part (evaluation/ros2.py): one row per step and per topic."""
    os.makedirs(build_root, exist_ok=True)
    print('ROS 2: the ROS 2 wheels of %s' % ros2.WHEELS, flush=True)
    if not ros2.wheels_found():
        steps.skip('ROS 2: colcon build --mros-export of test_ws_ros2',
                   'no ROS 2 wheels at %s (scripts/setup.sh --tests makes them)' % ros2.WHEELS)
        return
    workspace = steps.run('ROS 2: colcon build --mros-export of test_ws_ros2 (the ROS 2 wheels\' '
                          'rosidl_default_generators and the mros2 generator)',
                          ros2.colcon_build, os.path.join(build_root, 'ws'))
    if workspace is None:
        return
    programs = {}
    for target in ros2.FIRMWARE_TARGETS:
        programs[target.name] = steps.run(
            'ROS 2: firmware (CMake, mros2_import_messages) for %s' % target.title,
            ros2.build_firmware, workspace, os.path.join(build_root, 'firmware', target.name),
            target)
    linux = programs['arm-linux-gnueabihf']
    if linux is None:
        steps.skip('ROS 2: the board under qemu-arm with rclpy nodes',
                   'its firmware did not build')
        return
    steps.run("ROS 2: the fit check's verdict (genmros mros2-fit, the board's endpoints)",
              ros2.fit_verdict, workspace, linux)
    print('ROS 2: the board under qemu-arm with rclpy nodes; %s ...' % ros2.TRANSPORT, flush=True)
    try:
        for title, detail, problem in ros2.exchange(workspace, linux):
            steps.add('ROS 2: ' + title, detail, problem)
    except (board.Failure, OSError) as error:
        steps.add('ROS 2: the board under qemu-arm with rclpy nodes', '', _first_line(error))
    # Before the field is added: the peer's samples are of Reading as it is.
    run_mros2_pc(steps, workspace, os.path.join(build_root, 'mros2_pc'))
    steps.run('ROS 2: in sync by construction: a field added, colcon build, firmware rebuilt',
              lambda: (None, ros2.in_sync(
                  workspace, os.path.join(build_root, 'firmware', 'arm-linux-gnueabihf'),
                  os.path.join(build_root, 'in_sync.log'))))
    posix_root = os.environ.get('MROS2_POSIX_ROOT', '')
    if not posix_root:
        print('\nthe real mros2-posix app was not run: MROS2_POSIX_ROOT is not set '
              '(docs/mros2.md, "mros2-posix with genmros").', flush=True)
        return
    title = 'ROS 2: the mros2-posix app (mros2 %s) with an rclpy node over a veth pair'
    problem = mros2_posix.checkout_problem(posix_root)
    if problem:
        steps.skip(title % 'as pinned', problem)
        return
    if os.geteuid() != 0:
        print('\nthe real mros2-posix app was not run: it needs root for the network '
              'namespace.', flush=True)
        return
    steps.run(title % 'as pinned, one publisher', ros2.posix_run, posix_root,
              os.path.join(build_root, 'mros2_posix'))
    mros2_root = os.environ.get('MROS2_ROOT', '')
    if mros2_root:
        steps.run(title % 'v0.5.4 patched, two publishers', ros2.posix_run, posix_root,
                  os.path.join(build_root, 'mros2_posix_patched'), mros2_root)


def run_mros2_pc(steps, workspace, build_root):
    """The main job's mros2 app on the user's mros2 (MROS2_ROOT), twice: one row per topic."""
    mros2_root = os.environ.get('MROS2_ROOT', '')
    runs = (('mros2 as it is + accept-fast-dds-3-discovery, reader-catches-up-at-once, '
             'one publisher', False),
            ('mros2 --hardened, seven publishers, one reliable, a service each way', True))
    if not mros2_root or not os.path.isfile(os.path.join(mros2_root, 'src', 'mros2.cpp')):
        reason = 'MROS2_ROOT is not set' if not mros2_root else \
            'no mros2 checkout at %s (no src/mros2.cpp)' % mros2_root
        print('\nthe main job\'s mros2 app on your mros2 (genmros mros2-pc: %s) was not run: %s. '
              'Set MROS2_ROOT=<your checkout of mROS-base/mros2 with its embeddedRTPS> to run '
              'it as well.' % (' and '.join(name for name, _ in runs), reason), flush=True)
        return
    for name, hardened in runs:
        title = 'ROS 2 on mros2 (%s)' % name
        print('%s: evaluation/mros2_app under qemu-arm, rclpy on its network ...' % title,
              flush=True)
        try:
            rows, output = ros2.mros2_pc_run(workspace, os.path.join(
                build_root, 'hardened' if hardened else 'as_it_is'), mros2_root, hardened)
        except (board.Failure, AssertionError, RuntimeError, OSError) as error:
            steps.add(title, '', _first_line(error))
            continue
        for row_title, detail, problem in rows:
            steps.add('%s: %s' % (title, row_title), detail, problem)
        peaks = [line.strip() for line in output.splitlines() if ' of ' in line and '%' in line]
        print('  stacks: ' + '; '.join(' '.join(line.split()[:5]) for line in peaks), flush=True)
    run_plain_node(steps, mros2_root, build_root)


def run_plain_node(steps, mros2_root, build_root):
    """The plain node (what a user's node does) against a hardened board of the soak's app
    three_echoes under qemu-arm, and against the control, an rclpy node in the board's place
    (testing/mros2_soak.py): one row each, every reply exact."""
    from rosbags.typesys import Stores, get_typestore
    posix_root = os.environ.get('MROS2_POSIX_ROOT', '')
    title = 'ROS 2 on mros2 (--hardened): the plain node and three_echoes under qemu-arm'
    if not os.path.isfile(os.path.join(posix_root, 'include', 'rtps', 'config.h')):
        print('\n%s, and its control, were not run: MROS2_POSIX_ROOT is not set (the soak\'s '
              "board config is mros2-posix' include/rtps/config.h)." % title, flush=True)
        return
    case = mros2_soak.CASES['arm-small']
    address = mros2_soak.ADDRESSES[0]
    work = os.path.join(build_root, 'plain_node')
    programs = mros2_soak.build_programs(case, posix_root, mros2_root, work,
                                         addresses=(address,))
    typestore = get_typestore(Stores.ROS2_HUMBLE)

    def exchange(control):
        start = mros2_soak.run_start(programs[address], case, typestore, os.path.join(
            work, 'control' if control else 'board'), 0, control=control)
        if not start.passed:
            raise AssertionError(start.problem)
        return start, '%d of %d replies exact, the node matched after %.2f s' % (
            start.arrived, start.expected, start.node_matched_after)
    steps.run(title, exchange, False)
    steps.run('ROS 2 control: the plain node and an rclpy node in the board\'s place',
              exchange, True)


def run_mros_v1(steps, workspace, mros_root, build_root, count):
    """The paper's evaluation on the user's library: one row per direction."""
    os.makedirs(build_root, exist_ok=True)
    program = steps.run('the evaluation app on the mROS v1 library of %s (genmros mros-v1-pc)'
                        % mros_root,
                        lambda: (mros_v1.build_app(mros_root, build_root), 'built for qemu-arm'))
    if program is None:
        return
    print('the paper\'s evaluation on the mROS v1 library, under qemu-arm ...', flush=True)
    directions, boards = mros_v1.run(workspace, program, count, build_root)
    for direction in directions:
        steps.add(direction.title, direction.detail(), direction.problem)
    print("  the board's task stacks, the deepest of its runs (bytes): " + ', '.join(
        '%s %d of %d' % (task, peak, size)
        for task, (peak, size) in mros_v1.stack_peaks(boards).items()))


def finish(steps):
    print('\n==== the main job ====')
    print(steps.table())
    print('RESULT: %s' % ('PASS' if steps.passed() else 'FAIL'))
    return 0 if steps.passed() else 1


if __name__ == '__main__':
    sys.exit(main())
