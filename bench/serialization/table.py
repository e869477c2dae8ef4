"""Runs the serialization benchmark's sides and prints the table.

Every measurement is a process of its own (bench_<side> INSTANCE OPERATION
SECONDS), so each side starts with the same fresh allocator, warms up, and
reports the median time per call over its batches. The sides run in rounds,
in a different order each round, so drift of the machine's speed hits them
alike; a ratio is the median of the per-round ratios, with their range.

Usage: table.py BUILD_DIR [--rounds N] [--seconds S]
"""

import argparse
import os
import statistics
import subprocess

# The columns: roscpp is the reference, genmros the heap storage every ROS
# build gets, bounded genmros' heap-free storage, memcpy the floor for large
# payloads (a bare copy of the same wire image).
SIDES = ['roscpp', 'genmros', 'bounded', 'memcpy']
OPERATIONS = ['encode', 'decode']


def measure(build_dir, side, instance, operation, seconds):
    output = subprocess.run([os.path.join(build_dir, 'bench_' + side), str(instance), operation, str(seconds)],
                            capture_output=True, text=True, check=True).stdout.split()
    return int(output[0]), float(output[1])


def instances(build_dir):
    listing = subprocess.run([os.path.join(build_dir, 'bench_genmros'), 'list'],
                             capture_output=True, text=True, check=True).stdout
    return [(name, large == '1') for name, large in (line.split('\t') for line in listing.splitlines())]


def ratio_cell(rounds, numerator, denominator):
    """median (min-max) of numerator's time / denominator's time per round."""
    ratios = [r[numerator] / r[denominator] for r in rounds]
    return '%.2fx (%.2f-%.2f)' % (statistics.median(ratios), min(ratios), max(ratios))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('build_dir')
    parser.add_argument('--rounds', type=int, default=7)
    parser.add_argument('--seconds', type=float, default=0.25, help='per measurement')
    arguments = parser.parse_args()
    built = [s for s in SIDES if os.path.exists(os.path.join(arguments.build_dir, 'bench_' + s))]

    rows = []
    for index, (name, large) in enumerate(instances(arguments.build_dir)):
        sides = [s for s in built if s != 'memcpy' or large]
        for operation in OPERATIONS:
            rounds = []
            for round_number in range(arguments.rounds):
                order = sides[round_number % len(sides):] + sides[:round_number % len(sides)]
                times = {}
                for side in order:
                    size, times[side] = measure(arguments.build_dir, side, index, operation, arguments.seconds)
                rounds.append(times)
            rows.append((name, operation, size, sides, rounds))

    print('Median ns per call over %d rounds (each a fresh process per side: warm-up, then the median of 15 '
          'batches); speed ratios are roscpp time / genmros time, median (min-max) of the rounds.'
          % arguments.rounds)
    print()
    header = ['message', 'op', 'bytes', 'roscpp ns', 'genmros ns', 'genmros vs roscpp',
              'bounded ns', 'bounded vs roscpp', 'memcpy ns', 'genmros / memcpy']
    print('| ' + ' | '.join(header) + ' |')
    print('|' + '|'.join(['---'] * 2 + ['---:'] * (len(header) - 2)) + '|')
    for name, operation, size, sides, rounds in rows:
        def median_ns(side):
            return '%.1f' % statistics.median(r[side] for r in rounds) if side in sides else '-'
        cells = [name, operation, str(size), median_ns('roscpp'), median_ns('genmros'),
                 ratio_cell(rounds, 'roscpp', 'genmros'),
                 median_ns('bounded'),
                 ratio_cell(rounds, 'roscpp', 'bounded') if 'bounded' in sides else '-',
                 median_ns('memcpy'),
                 ratio_cell(rounds, 'genmros', 'memcpy') if 'memcpy' in sides else '-']
        print('| ' + ' | '.join(cells) + ' |')


if __name__ == '__main__':
    main()
