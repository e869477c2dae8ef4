#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""What genmros' mros2 patch set costs on the wire: round trips and throughput between an
mros2 board on the PC target and rclpy, mros2 as it is against --hardened, in one run.

    MROS2_ROOT=... MROS2_POSIX_ROOT=... /usr/bin/python3 bench/mros2/pc_round_trip.py
        [--runs 5] [--trips 200] [--burst 1000] [--keep DIR] [--qos]

mros2-posix' echoreply_string (MROS2_POSIX_ROOT's workspace/, its include/rtps/config.h) is
built with genmros mros2-pc for this PC, without sanitizers, twice: with MROS2_ROOT as it
is plus accept-fast-dds-3-discovery and reader-catches-up-at-once (without which it
discovers no Fast DDS 3 node, or matches it late), and --hardened. Each run starts the
board on its own network and round_trip_peer.py (rclpy,
the ROS 2 wheels) on its ROS side: --trips round trips one at a time, then --burst strings
at once (best-effort: what is lost is counted). For orientation, rclpy_echo.py stands in
for the board in the same place, rclpy on both sides. The builds take turns, run after run;
each cell is the median of the runs' values (a run's round trip: its median).

--qos compares instead, on one --hardened build of testing/mros2_pc_apps/reliable_echo, its
best-effort echo (plain -> plain_echo, the peer best-effort) and its reliable one (text ->
text_echo: mros2::QoS(10).reliable() on the board, reliable and keeping all in rclpy), the
pairs taking turns run after run; the burst is then one at once into each.
"""

import argparse
import json
import os
import shutil
import statistics
import subprocess
import sys
import tempfile

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, REPO)  # colcon_mros and the shared testing package
from testing import mros2_pc  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
PEER = os.path.join(HERE, 'round_trip_peer.py')
RCLPY_ECHO = os.path.join(HERE, 'rclpy_echo.py')
BUILDS = (('as it is + ' + ', '.join(mros2_pc.TALKING_PATCHES),
           {'patches': mros2_pc.TALKING_PATCHES}),
          ('--hardened', {'hardened': True}))
RCLPY = 'rclpy echo (orientation)'


# --qos: the reliable_echo app's two echoes, and the peer's arguments for each.
QOS_APP = os.path.join(REPO, 'testing', 'mros2_pc_apps', 'reliable_echo')
QOS_PAIRS = (('best-effort: plain -> plain_echo', ['--to', 'plain', '--back', 'plain_echo']),
             ('reliable: text -> text_echo', ['--to', 'text', '--back', 'text_echo',
                                              '--reliable']))


def run_peer(network, work_dir, trips, burst, arguments=()):
    result = subprocess.run(network.ros_command([os.path.join(mros2_pc.WHEELS_VENV, 'bin',
                                                              'python'), PEER, str(trips),
                                                 str(burst), *arguments]),
                            capture_output=True, text=True, timeout=600,
                            env=mros2_pc.peer_environment(work_dir))
    if result.returncode != 0:
        raise SystemExit('the peer failed: %s' % result.stderr[-2000:])
    return json.loads(result.stdout)


def run_board(program, work_dir, trips, burst, ready='ready to pub/sub message',
              arguments=()):
    with mros2_pc.Session(program, work_dir) as session:
        session.start_board()
        session.wait_for_output(ready)
        report = run_peer(session.network, work_dir, trips, burst, arguments)
        session.stop_board()
    return report


def run_rclpy(work_dir, trips, burst):
    from colcon_mros.library_tools.mros2.pc_target.network import BoardNetwork
    with BoardNetwork('192.168.11.3', 0) as network:
        echo = subprocess.Popen(network.board_command(
            [os.path.join(mros2_pc.WHEELS_VENV, 'bin', 'python'), RCLPY_ECHO]),
            env=mros2_pc.peer_environment(work_dir))
        try:
            return run_peer(network, work_dir, trips, burst)
        finally:
            echo.terminate()
            echo.wait(timeout=60)


def run_builds(options, work, mros2_root, posix_root, config):
    """{row: [peer reports]}: echoreply_string as it is and hardened, and rclpy's echo."""
    app = os.path.join(work, 'echoreply_string')
    if not os.path.isdir(app):
        shutil.copytree(os.path.join(posix_root, 'workspace', 'echoreply_string'), app)
    programs = {name: mros2_pc.build(app, os.path.join(work, 'build-%d' % index), mros2_root,
                                     config, target='native', **build)
                for index, (name, build) in enumerate(BUILDS)}
    results = {name: [] for name in list(programs) + [RCLPY]}
    for run in range(options.runs):
        for name, program in programs.items():
            results[name].append(run_board(program, work, options.trips, options.burst))
        results[RCLPY].append(run_rclpy(work, options.trips, options.burst))
        print('run %d of %d done' % (run + 1, options.runs), file=sys.stderr, flush=True)
    return results


def run_qos(options, work, mros2_root, config):
    """{row: [peer reports]}: reliable_echo's best-effort and reliable echoes."""
    program = mros2_pc.build(QOS_APP, os.path.join(work, 'build-qos'), mros2_root, config,
                             target='native', hardened=True)
    results = {name: [] for name, _ in QOS_PAIRS}
    for run in range(options.runs):
        for name, arguments in QOS_PAIRS:
            results[name].append(run_board(program, work, options.trips, options.burst,
                                           'app ready', arguments))
        print('run %d of %d done' % (run + 1, options.runs), file=sys.stderr, flush=True)
    return results


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('--runs', type=int, default=5)
    parser.add_argument('--trips', type=int, default=200)
    parser.add_argument('--burst', type=int, default=1000)
    parser.add_argument('--keep', help='build and log here (default: a temporary directory)')
    parser.add_argument('--qos', action='store_true',
                        help="reliable_echo's best-effort and reliable echoes, hardened")
    options = parser.parse_args()
    mros2_root = os.environ.get('MROS2_ROOT')
    posix_root = os.environ.get('MROS2_POSIX_ROOT')
    if not mros2_root or not posix_root:
        print('pc_round_trip.py: needs MROS2_ROOT (mros2 v0.5.4) and MROS2_POSIX_ROOT (its '
              'example apps): docs/testing.md', file=sys.stderr)
        return 2
    work = options.keep or tempfile.mkdtemp(prefix='mros2_round_trip_')
    config = os.path.join(posix_root, 'include', 'rtps', 'config.h')
    results = run_qos(options, work, mros2_root, config) if options.qos else \
        run_builds(options, work, mros2_root, posix_root, config)
    rows = {}
    for name, reports in results.items():
        trips = [statistics.median(report['round_trips_us']) for report in reports]
        rates = [report['echoed'] / report['burst_seconds'] for report in reports
                 if report['burst_seconds']]
        rows[name] = (trips, rates, [report['echoed'] for report in reports])
    base = list(results)[0]
    base_trip = statistics.median(rows[base][0])
    base_rate = statistics.median(rows[base][1])
    print('| echo | round trip, median (µs) | runs\' range | ratio | echoes/s in a burst of %d '
          '| runs\' range | ratio | echoed of %d (range) |' % (options.burst, options.burst))
    print('|---|---:|---:|---:|---:|---:|---:|---:|')
    for name, (trips, rates, echoed) in rows.items():
        trip, rate = statistics.median(trips), statistics.median(rates)
        print('| %s | %.0f | %.0f-%.0f | %.3f | %.0f | %.0f-%.0f | %.3f | %d (%d-%d) |'
              % (name, trip, min(trips), max(trips), trip / base_trip, rate, min(rates),
                 max(rates), rate / base_rate, statistics.median(echoed), min(echoed),
                 max(echoed)))
    print('\n%d runs each, builds taking turns; --trips %d; native, no sanitizer; %s'
          % (options.runs, options.trips, work))


if __name__ == '__main__':
    sys.exit(main())
