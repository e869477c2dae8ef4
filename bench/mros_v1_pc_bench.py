#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Throughput and latency of the real mROS v1 library on the PC target
against roscpp, side by side in one run: the library's talker
(bench/mros_v1_pc/, built natively by genmros mros-v1-pc with
custom_pubsub's configuration and app.h) -> a roscpp node, the same
talker on the library with genmros' patch set (--hardened),
and a roscpp talker (mros_test_nodes bench_talker) -> the same roscpp node,
both with mros_test/PersonalData, through a real rosmaster on a free
loopback port. The library's sample memory pools hold at most 1 KiB a
message, so no image is sent. Information, not a goal: the library is not
ours.

Latency: messages at a fixed rate, send time (just before publish) to the
roscpp subscriber's callback, CLOCK_MONOTONIC on both sides. Throughput:
messages published as fast as each side goes (roscpp: as fast as publish()
returns; the library's task gives up the CPU after each publish, as an ASP
task must for the library to send), divided by the time from the first send
to the last arrival; the share delivered is shown beside it.
Prints a table with ratios (hardened / as it is, mROS v1 / roscpp).

  bench/mros_v1_pc_bench.py [--build-dir DIR] [--rounds N]

with the installed genmros (scripts/setup.sh --tests) and the mROS v1
checkout in MROS_V1_ROOT.
"""

import argparse
import os
import shutil
import statistics
import subprocess
import sys
import tempfile

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# testing/, what the tests, the benches and the main job share, is not installed:
# it comes from this repository, after the installed genmros.
sys.path.append(REPO)

from testing.ros_graph import CatkinWorkspace, RosGraph, board_environment  # noqa: E402

TEST_WS_SRC = os.path.join(REPO, 'test_ws', 'src')
TALKER_APP = os.path.join(REPO, 'bench', 'mros_v1_pc')

# (count, rate per second; 0: as fast as publish() returns)
LATENCY = (2000, 1000)
THROUGHPUT = (5000, 0)


def read_times(path):
    times = {}
    with open(path) as lines:
        for line in lines:
            sequence, stamp = line.split()
            times[int(sequence)] = int(stamp)
    return times


def run_once(graph, talker_argv, listener_argv, scratch, tag, talker_env=None):
    """Runs one talker -> listener transfer; returns (send, receive) times.
    The send times' file is the talker's last argument, or, with talker_env,
    the value of its MROS_BENCH ("COUNT RATE FILE")."""
    send_path = os.path.join(scratch, tag + '.send')
    receive_path = os.path.join(scratch, tag + '.receive')
    listener = graph.start('bench_listener ' + tag, listener_argv + [receive_path])
    graph.wait_for_graph(subscribers=[('/bench', '/ros_bench_listener')])
    if talker_env is not None:
        talker_env = dict(talker_env, MROS_BENCH='%s %s' % (talker_env['MROS_BENCH'], send_path))
        talker = graph.start('bench_talker ' + tag, talker_argv, talker_env)
    else:
        talker = graph.start('bench_talker ' + tag, talker_argv + [send_path])
    talker.popen.wait(timeout=300)
    listener.popen.wait(timeout=60)
    assert talker.popen.returncode == 0, talker.output()
    assert listener.popen.returncode == 0, listener.output()
    return read_times(send_path), read_times(receive_path)


def latency_stats(send, receive):
    latencies = sorted((receive[s] - send[s]) / 1000.0 for s in receive if s in send)

    def percentile(p):
        return latencies[min(len(latencies) - 1, int(p / 100.0 * len(latencies)))]
    return {'p50': percentile(50), 'p90': percentile(90), 'p99': percentile(99),
            'delivered': len(latencies) / float(len(send))}


def throughput_stats(send, receive):
    span = (max(receive.values()) - min(send.values())) / 1e9
    return {'rate': len(receive) / span, 'delivered': len(receive) / float(len(send))}


def measure(graph, workspace, talker, on_board, scratch, tag):
    """Latency and throughput of one talker -> the roscpp listener; an app
    on the board (on_board) gets its own ports each run."""
    results = {}
    for (count, rate), kind in ((LATENCY, 'latency'), (THROUGHPUT, 'flood')):
        listener = workspace.roscpp('bench_listener', 'personal', str(count), '3')
        if on_board:
            argv = talker
            environment = dict(board_environment(), MROS_BENCH='%d %d' % (count, rate))
        else:
            argv, environment = talker + [str(count), str(rate)], None
        send, receive = run_once(graph, argv, listener, scratch, '%s-%s' % (tag, kind),
                                 environment)
        if kind == 'latency':
            results.update(latency_stats(send, receive))
        else:
            flood = throughput_stats(send, receive)
            results['rate'] = flood['rate']
            results['flood_delivered'] = flood['delivered']
    return results


def build(mros_root, build_root):
    """(the ROS nodes of test_ws, {library: the talker program}), built in
    build_root, on the library as it is and hardened."""
    shutil.copytree(TEST_WS_SRC, os.path.join(build_root, 'test_ws', 'src'), dirs_exist_ok=True)
    workspace = CatkinWorkspace(os.path.join(build_root, 'test_ws'), 'mros_test_nodes')
    workspace.build(os.path.join(build_root, 'catkin_make.log'), '-DCMAKE_BUILD_TYPE=Release')
    talker = shutil.copytree(TALKER_APP, os.path.join(build_root, 'talker'), dirs_exist_ok=True)
    for sample_file in ('mros_config', 'app.h'):  # custom_pubsub's configuration and tasks
        if not os.path.lexists(os.path.join(talker, sample_file)):
            os.symlink(os.path.join(mros_root, 'mros_ws', 'custom_pubsub', sample_file),
                       os.path.join(talker, sample_file))
    programs = {}
    for library, flags in (('mros_v1', []), ('mros_v1_hardened', ['--hardened'])):
        output = os.path.join(build_root, 'talker-build-' + library)
        subprocess.run(['genmros', 'mros-v1-pc', talker, '--target', 'native', '--mros-v1-root',
                        mros_root, '--workspace', TEST_WS_SRC, '--type', 'mros_test/PersonalData',
                        '-o', output, '--build-only'] + flags, check=True)
        programs[library] = os.path.join(output, 'bench_talker')
    return workspace, programs


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('--build-dir', help='keep the builds here (default: a temporary dir)')
    parser.add_argument('--rounds', type=int, default=1,
                        help='alternate the library and roscpp this many times; medians are shown')
    args = parser.parse_args()
    mros_root = os.environ.get('MROS_V1_ROOT', '')
    if not os.path.isfile(os.path.join(mros_root, 'mros-lib', 'Makefile.m')):
        print("%s: needs an mROS v1 checkout: set MROS_V1_ROOT (no mros-lib/Makefile.m at '%s')"
              % (os.path.basename(sys.argv[0]), mros_root), file=sys.stderr)
        return 2
    samples = {'mros_v1': [], 'mros_v1_hardened': [], 'roscpp': []}
    with tempfile.TemporaryDirectory(prefix='mros_v1_pc_bench_') as scratch:
        workspace, programs = build(mros_root, os.path.abspath(args.build_dir or scratch))
        with RosGraph(workspace.environment()) as graph:
            for round_index in range(args.rounds):
                for library, program in programs.items():
                    samples[library].append(measure(graph, workspace, [program], True, scratch,
                                                    '%s-%d' % (library, round_index)))
                samples['roscpp'].append(measure(graph, workspace,
                                                 workspace.roscpp('bench_talker', 'personal'),
                                                 False, scratch, 'roscpp-%d' % round_index))
    print_table(samples, args.rounds)
    return 0


def print_table(samples, rounds):
    rows = [('throughput [msg/s]', 'rate', '%.0f'),
            ('delivered when flooding', 'flood_delivered', '%.3f'),
            ('latency p50 [us]', 'p50', '%.0f'),
            ('latency p90 [us]', 'p90', '%.0f'),
            ('latency p99 [us]', 'p99', '%.0f'),
            ('delivered at %d/s' % LATENCY[1], 'delivered', '%.3f')]
    print('\nPersonalData to a roscpp node: the real mROS v1 library (PC target, native), as it '
          'is and hardened, vs. roscpp (same machine, one run, median of %d alternating '
          'round(s))' % rounds)
    print('| metric | mROS v1 | mROS v1 hardened | roscpp | hardened/as it is | '
          'mROS v1/roscpp |')
    print('|---|---:|---:|---:|---:|---:|')

    def ratio(numerator, denominator):
        return numerator / denominator if denominator else 0
    for label, key, fmt in rows:
        mros, hardened, roscpp = (statistics.median(r[key] for r in samples[name])
                                  for name in ('mros_v1', 'mros_v1_hardened', 'roscpp'))
        print('| %s | %s | %s | %s | %.2f | %.2f |' % (
            label, fmt % mros, fmt % hardened, fmt % roscpp, ratio(hardened, mros),
            ratio(mros, roscpp)))


if __name__ == '__main__':
    sys.exit(main())
