#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""The soak: fresh starts of a hardened mros2 board on the PC target against the plain node
(an rclpy node that does what a user's does: it waits for matching through the graph API,
then 3 s, sends each sample once, 100 ms apart, and waits 30 s for the replies); every
sample of every start must arrive.

    MROS2_ROOT=... MROS2_POSIX_ROOT=... /usr/bin/python3 bench/mros2/soak.py
        [--starts 50] [--case NAME ...] [--without PATCH ...] [--no-control] [--keep DIR]

The cases (testing/mros2_soak.py): arm-small and native-small (--sanitize): the app
three_echoes (three subscriptions, three publishers, each callback changes its sample and
publishes it), 20 samples per topic each way; arm-large and native-large: fragment_echo, 10
strings of 30 KB in at a receive limit of 1472 (FRAGMENT_BUFFER_SIZE 32768, a reader queue
of 64, the node on genmros' Fast DDS profile), each echoed back. Starts alternate between
mros2-posix' address and 10.77.3.9, and between board first and node first. --without
builds the series without those patches (the figures before a fix). The control runs an
rclpy node in the board's place (testing/mros2_pc_control.py) with the same node, 10
starts per case kind, unless --no-control. One line per start, then the table.
"""

import argparse
import os
import statistics
import sys
import tempfile
import time

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path[:0] = [REPO, os.path.join(REPO, 'build', 'test-python')]  # testing/, rosbags
from colcon_mros.library_tools.mros2.patches import mros2_patches  # noqa: E402
from testing import mros2_soak  # noqa: E402

CONTROL_STARTS = int(os.environ.get("SOAK_CONTROL_STARTS", 10))


def seconds(values):
    values = [value for value in values if value is not None]
    if not values:
        return '-', '-'
    return '%.2f' % statistics.median(values), '%.2f' % max(values)


def soak(case, programs, typestore, work, starts, control=False):
    results = []
    for index in range(starts):
        program = programs[mros2_soak.ADDRESSES[index % len(mros2_soak.ADDRESSES)]]
        start = mros2_soak.run_start(program, case, typestore,
                                     os.path.join(work, '%s-%s%d' % (
                                         case.name, 'control-' if control else '', index)),
                                     index, control=control)
        results.append(start)
        print('%s%s %d: %s, %s, %s: %d of %d%s, board matched after %s s' % (
            case.name, ' (control)' if control else '', index, 'passed' if start.passed
            else 'FAILED', start.address, start.order, start.arrived, start.expected,
            '' if start.passed else ' (%s)' % start.problem,
            '-' if start.board_matched_after is None else '%.2f' % start.board_matched_after),
            flush=True)
    return results


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('--starts', type=int, default=50)
    parser.add_argument('--case', action='append', choices=sorted(mros2_soak.CASES))
    parser.add_argument('--without', action='append', default=[], metavar='PATCH')
    parser.add_argument('--no-control', action='store_true')
    parser.add_argument('--keep', help='build and log here (default: a temporary directory)')
    options = parser.parse_args()
    mros2_root = os.environ.get('MROS2_ROOT')
    posix_root = os.environ.get('MROS2_POSIX_ROOT')
    if not mros2_root or not posix_root:
        print('soak.py: needs MROS2_ROOT (mros2 v0.5.4) and MROS2_POSIX_ROOT (its config): '
              'docs/testing.md', file=sys.stderr)
        return 2
    names = [patch.name for patch in mros2_patches()]
    unknown = sorted(set(options.without) - set(names))
    if unknown:
        parser.error('not in the series: %s' % ', '.join(unknown))
    patches = [name for name in names if name not in options.without] \
        if options.without else None
    from rosbags.typesys import Stores, get_typestore
    typestore = get_typestore(Stores.ROS2_HUMBLE)
    work = options.keep or tempfile.mkdtemp(prefix='mros2_soak_')
    rows = []
    controlled = set()
    for name in options.case or list(mros2_soak.CASES):
        case = mros2_soak.CASES[name]
        programs = mros2_soak.build_programs(case, posix_root, mros2_root, work, patches)
        began = time.monotonic()
        results = soak(case, programs, typestore, work, options.starts)
        rows.append((name, results, time.monotonic() - began))
        if not options.no_control and case.large not in controlled:
            controlled.add(case.large)
            began = time.monotonic()
            results = soak(case, programs, typestore, work, CONTROL_STARTS, control=True)
            rows.append(('control (%s)' % ('large' if case.large else 'small'), results,
                         time.monotonic() - began))
    print('\n| case | starts passed | the board matched the node, median / worst (s) | '
          'the node matched, median / worst (s) | time (s) |')
    print('|---|---:|---:|---:|---:|')
    for name, results, took in rows:
        print('| %s | %d of %d | %s / %s | %s / %s | %.0f |' % (
            name, sum(start.passed for start in results), len(results),
            *seconds(start.board_matched_after for start in results),
            *seconds(start.node_matched_after for start in results), took))
    without = ' without %s' % ', '.join(options.without) if options.without else ''
    print('\nthe series%s; times from the later of the node\'s start and the board\'s "app '
          'ready"; %s' % (without, work))
    return 0 if all(start.passed for _, results, _ in rows for start in results) else 1


if __name__ == '__main__':
    sys.exit(main())
