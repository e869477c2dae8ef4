#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""The services soak: fresh starts of the hardened service_pair board on the PC target
against the service peer (rclpy, testing/mros2_pc_services.py); every call of every start,
both ways, must come back right.

    MROS2_ROOT=... MROS2_POSIX_ROOT=... /usr/bin/python3 bench/mros2/service_soak.py
        [--starts 20] [--target native|arm ...] [--calls 20] [--keep DIR]

Each start: a fresh board (testing/mros2_pc_apps/service_pair: it serves parameter_types and
calls rclpy's name_lengths 100 times) and a fresh peer, board first and node first in turn.
The peer waits for the service through rclpy's graph API (wait_for_service), calls it
--calls times one by one, from 3 clients at once (10 calls each in flight), once from a
client it destroys before the reply and --calls times more, and serves the board's 100 calls.
A start passes when every reply both ways is right, the board refused no reply, and rclpy
lists the service by the board's node (testing/mros2_soak.service_problems). Native builds
are sanitized. One line per start, then the table.
"""

import argparse
import os
import statistics
import sys
import tempfile
import time

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path[:0] = [REPO, os.path.join(REPO, 'build', 'test-python')]  # testing/
from testing import mros2_pc, mros2_soak  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('--starts', type=int, default=20)
    parser.add_argument('--target', action='append', choices=('native', 'arm'))
    parser.add_argument('--calls', type=int, default=20)
    parser.add_argument('--keep', help='build and log here (default: a temporary directory)')
    options = parser.parse_args()
    mros2_root, posix_root = os.environ.get('MROS2_ROOT'), os.environ.get('MROS2_POSIX_ROOT')
    if not mros2_root or not posix_root:
        print('service_soak.py: needs MROS2_ROOT (mros2 v0.5.4) and MROS2_POSIX_ROOT (its '
              'config): docs/testing.md', file=sys.stderr)
        return 2
    work = options.keep or tempfile.mkdtemp(prefix='mros2_service_soak_')
    config = mros2_soak.changed_config(posix_root, work, [mros2_soak.LONG_TYPE_NAMES])
    rows = []
    for target in options.target or ['native', 'arm']:
        program = mros2_pc.build(mros2_soak.SERVICE_PAIR, os.path.join(work, 'build-' + target),
                                 mros2_root, config, hardened=True, target=target,
                                 sanitize=target == 'native')
        began = time.monotonic()
        results = []
        for index in range(options.starts):
            start = mros2_soak.run_service_start(
                program, os.path.join(work, '%s-%d' % (target, index)), index, options.calls)
            results.append(start)
            print('%s %d: %s, %s, calls done after %.1f s%s' % (
                target, index, 'passed' if start.passed else 'FAILED', start.order, start.took,
                '' if start.passed else ' (%s)' % start.problem), flush=True)
        rows.append((target, results, time.monotonic() - began))
    print('\n| target | starts passed | calls done after, median / worst (s) | time (s) |')
    print('|---|---:|---:|---:|')
    for target, results, took in rows:
        print('| %s | %d of %d | %.1f / %.1f | %.0f |' % (
            target, sum(start.passed for start in results), len(results),
            statistics.median(start.took for start in results),
            max(start.took for start in results), took))
    print('\nper start: rclpy calls %d + %d, 3 clients x 10 at once, the board 100; %s'
          % (options.calls, options.calls, work))
    return 0 if all(start.passed for _, results, _ in rows for start in results) else 1


if __name__ == '__main__':
    sys.exit(main())
