#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""A service call's round trip: rclpy calling an mros2 board's service on the PC target
against rclpy calling an rclpy service in the same place, in one run.

    MROS2_ROOT=... MROS2_POSIX_ROOT=... /usr/bin/python3 bench/mros2/service_round_trip.py
        [--runs 5] [--calls 200] [--target native] [--keep DIR]

testing/mros2_pc_apps/service_pair (it serves parameter_types, rcl_interfaces/srv/
GetParameterTypes; genmros' mros2 patch services-both-ways) is built --hardened for this PC
with mros2-posix' config, MAX_TYPENAME_LENGTH 64. Each run starts the board on its own
network and service_call_peer.py on its ROS side, which calls the service --calls times,
one at a time; then service_call_peer.py serves in the board's place, rclpy on both sides.
The two take turns, run after run; a cell is the median of the runs' medians. Prints a
Markdown table.
"""

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, REPO)  # colcon_mros and the shared testing package
from testing import mros2_pc, mros2_soak  # noqa: E402

PEER = os.path.join(os.path.dirname(os.path.abspath(__file__)), 'service_call_peer.py')
APP = os.path.join(REPO, 'testing', 'mros2_pc_apps', 'service_pair')
PYTHON = os.path.join(mros2_pc.WHEELS_VENV, 'bin', 'python')
BOARD, RCLPY = 'the board serves (mros2, --hardened)', 'rclpy serves (orientation)'


def calls(network, work_dir, count):
    result = subprocess.run(network.ros_command([PYTHON, PEER, 'call', str(count)]),
                            capture_output=True, text=True, timeout=900,
                            env=mros2_pc.peer_environment(work_dir))
    if result.returncode != 0:
        raise SystemExit('the peer failed: %s' % result.stderr[-2000:])
    return json.loads(result.stdout)


def board_run(program, work_dir, count):
    with mros2_pc.Session(program, work_dir) as session:
        session.start_board()
        session.wait_for_output('app ready')
        report = calls(session.network, work_dir, count)
        session.stop_board()
    return report


def rclpy_run(program, work_dir, count):
    from colcon_mros.library_tools.mros2.pc_target.network import BoardNetwork
    with BoardNetwork(program.board_address, program.domain_id) as network:
        server = subprocess.Popen(network.board_command([PYTHON, PEER, 'serve']),
                                  env=mros2_pc.peer_environment(work_dir))
        try:
            return calls(network, work_dir, count)
        finally:
            server.terminate()
            server.wait(timeout=60)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('--runs', type=int, default=5)
    parser.add_argument('--calls', type=int, default=200)
    parser.add_argument('--target', default='native', choices=('native', 'arm'))
    parser.add_argument('--keep', help='build and log here (default: a temporary directory)')
    options = parser.parse_args()
    mros2_root, posix_root = os.environ.get('MROS2_ROOT'), os.environ.get('MROS2_POSIX_ROOT')
    if not mros2_root or not posix_root:
        raise SystemExit('set MROS2_ROOT and MROS2_POSIX_ROOT (docs/testing.md)')
    work = options.keep or tempfile.mkdtemp(prefix='genmros_service_bench_')
    config = mros2_soak.changed_config(posix_root, work, [mros2_soak.LONG_TYPE_NAMES])
    program = mros2_pc.build(APP, os.path.join(work, 'build-%s' % options.target), mros2_root,
                             config, hardened=True, target=options.target)
    results = {BOARD: [], RCLPY: []}
    for run in range(options.runs):
        results[BOARD].append(board_run(program, work, options.calls))
        results[RCLPY].append(rclpy_run(program, work, options.calls))
        print('run %d of %d done' % (run + 1, options.runs), file=sys.stderr, flush=True)
    medians = {name: statistics.median(statistics.median(report['round_trips_us'])
                                       for report in reports)
               for name, reports in results.items()}
    print('| server | round trip, median | ratio | replies right |')
    print('|---|---:|---:|---:|')
    for name, reports in results.items():
        print('| %s | %.0f us | %.3f | %d of %d |' % (
            name, medians[name], medians[name] / medians[RCLPY],
            sum(report['right'] for report in reports),
            options.calls * len(reports)))
    print('\n%d runs of %d calls each, target %s; work in %s'
          % (options.runs, options.calls, options.target, work))


if __name__ == '__main__':
    main()
