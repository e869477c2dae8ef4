#!/usr/bin/env python3
"""Throughput and latency of the mROS POSIX node against roscpp, side by
side in one run: an mROS node (firmware bench_talker) -> a roscpp node, and
a roscpp node (mros_test_nodes bench_talker) -> the same roscpp node, for
mros_test/PersonalData and a 640x480 rgb8 sensor_msgs/Image, through a real
rosmaster on a free loopback port. With an mROS v1 checkout (MROS_V1_ROOT,
default ../shared/mros_v1), a third column, for information: the real mROS
v1 library on the PC target, built natively (bench/mros_v1_pc/app.cpp), for
PersonalData at a fixed rate only (its sample memory pools hold at most 1 KiB
a message, and by the code of its publish() an empty pool is not handled).

Latency: messages at a fixed rate, send time (just before publish) to the
roscpp subscriber's callback, CLOCK_MONOTONIC on both sides. Throughput:
messages published as fast as publish() returns, with unbounded queues on
both sides (nothing dropped), divided by the time from the first send to the
last arrival. Not a test: it prints a table with ratios (mROS / roscpp).

  bench/posix_bench.py [--build-dir DIR] [--rounds N] [--kinds personal,image]
"""

import argparse
import os
import statistics
import sys
import tempfile

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(REPO, 'tests'))

import mros_v1_pc_evaluation  # noqa: E402
import posix_builds  # noqa: E402
from ros_processes import RosGraph, sourced_environment  # noqa: E402

# kind -> (latency: count, rate) and (throughput: count)
WORKLOADS = {
    'personal': {'title': 'PersonalData', 'latency': (2000, 1000), 'throughput': 50000},
    'image': {'title': 'Image 640x480 rgb8', 'latency': (150, 30), 'throughput': 300},
}


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


def measure_real_library(graph, workspace, program, scratch, round_index):
    """The real mROS v1 library's talker, PersonalData at a fixed rate."""
    count, rate = WORKLOADS['personal']['latency']
    environment = dict(mros_v1_pc_evaluation.board_environment(),
                       MROS_BENCH='%d %d' % (count, rate))
    send, receive = run_once(graph, [program],
                             workspace.roscpp('bench_listener', 'personal', str(count), '3'),
                             scratch, 'personal-mros_v1-latency-%d' % round_index, environment)
    return latency_stats(send, receive)


def measure(graph, workspace, firmware, kind, implementation, scratch, round_index):
    workload = WORKLOADS[kind]
    talker = (firmware.node('mros_bench_talker', kind) if implementation == 'mros'
              else workspace.roscpp('bench_talker', kind))
    results = {}
    count, rate = workload['latency']
    send, receive = run_once(graph, talker + [str(count), str(rate)],
                             workspace.roscpp('bench_listener', kind, str(count), '3'),
                             scratch, '%s-%s-latency-%d' % (kind, implementation, round_index))
    results.update(latency_stats(send, receive))
    count = workload['throughput']
    send, receive = run_once(graph, talker + [str(count), '0'],
                             workspace.roscpp('bench_listener', kind, str(count), '3'),
                             scratch, '%s-%s-flood-%d' % (kind, implementation, round_index))
    flood = throughput_stats(send, receive)
    results['rate'] = flood['rate']
    results['flood_delivered'] = flood['delivered']
    return results


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('--build-dir', help='keep the builds here (default: a temporary dir)')
    parser.add_argument('--rounds', type=int, default=1,
                        help='alternate mROS and roscpp this many times; medians are shown')
    parser.add_argument('--kinds', default=','.join(WORKLOADS),
                        help='message kinds to measure (default: %(default)s)')
    args = parser.parse_args()
    kinds = args.kinds.split(',')
    roots = (None, None)
    if args.build_dir:
        roots = tuple(os.path.join(os.path.abspath(args.build_dir), name)
                      for name in ('test_ws', 'firmware'))
        for root in roots:
            os.makedirs(root, exist_ok=True)
    workspace = posix_builds.workspace(roots[0])
    firmware = posix_builds.firmware(workspace.mros_export, roots[1])
    samples = {}
    with tempfile.TemporaryDirectory(prefix='posix_bench_') as scratch, \
            RosGraph(sourced_environment(workspace.setup_bash)) as graph:
        real_library = None
        if mros_v1_pc_evaluation.checkout_found():
            real_library = mros_v1_pc_evaluation.build_app(
                mros_v1_pc_evaluation.MROS_V1_ROOT, os.path.join(scratch, 'mros_v1'),
                os.path.join(REPO, 'bench', 'mros_v1_pc', 'app.cpp'), target='native')
        for round_index in range(args.rounds):
            for kind in kinds:
                for implementation in ('mros', 'roscpp'):
                    result = measure(graph, workspace, firmware, kind, implementation, scratch,
                                     round_index)
                    samples.setdefault((kind, implementation), []).append(result)
                if real_library and kind == 'personal':
                    samples.setdefault(('personal', 'mros_v1'), []).append(measure_real_library(
                        graph, workspace, real_library, scratch, round_index))
    print_table(samples, kinds, args.rounds)
    return 0


def print_table(samples, kinds, rounds):
    rows = [('throughput [msg/s]', 'rate', '%.0f', True),
            ('latency p50 [us]', 'p50', '%.0f', False),
            ('latency p90 [us]', 'p90', '%.0f', False),
            ('latency p99 [us]', 'p99', '%.0f', False),
            ('delivered at fixed rate', 'delivered', '%.3f', True),
            ('delivered when flooding', 'flood_delivered', '%.3f', True)]
    print('\nmROS POSIX node -> roscpp node vs. roscpp node -> roscpp node '
          '(same machine, one run, median of %d alternating round(s))' % rounds)
    print('| message | metric | mROS POSIX | roscpp | mROS/roscpp | real mROS v1 (PC target) |')
    print('|---|---|---:|---:|---:|---:|')
    for kind in kinds:
        workload = WORKLOADS[kind]
        for label, key, fmt, _ in rows:
            mros = statistics.median(r[key] for r in samples[(kind, 'mros')])
            roscpp = statistics.median(r[key] for r in samples[(kind, 'roscpp')])
            real = [r[key] for r in samples.get((kind, 'mros_v1'), []) if key in r]
            print('| %s | %s | %s | %s | %.2f | %s |' % (
                workload['title'], label, fmt % mros, fmt % roscpp,
                mros / roscpp if roscpp else 0, fmt % statistics.median(real) if real else 'n/a'))


if __name__ == '__main__':
    sys.exit(main())
