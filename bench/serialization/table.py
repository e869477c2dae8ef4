# SPDX-License-Identifier: BSD-3-Clause
"""Runs the serialization benchmark's sides and prints the table.

Every measurement is a process of its own (bench_SIDE.LAYOUT time INSTANCE
OPERATION SECONDS HEAP_SHIFT), so each side starts with a fresh allocator,
warms up, and reports the median time per call over its batches. The sides run in
rounds, in a different order each round, so drift of the machine's speed
hits them alike; a ratio is the median of the per-round ratios, with their
range.

Where code and data land decides a 64-character string's decode time more
than either library does: moving the same functions by 16 bytes, or the
heap by a few hundred, moves it between 15 and 18 ns (29 ns at worst) for
roscpp and genmros alike, and an executable has one layout of each. So each
round runs every side in the same one of four code layouts (run.sh links a
pad of 16 to 64 bytes before the side's code: bench_SIDE.LAYOUT) and with
the same heap shift (main.cpp), and the next round in others: the ratios
compare the libraries over layouts instead of two lucky or unlucky ones.

Where valgrind is installed, a second table counts the instructions of one
call, which no layout or neighbour on the machine changes: callgrind runs a
side for N and for 2N calls, and the difference is divided by N.

Usage: table.py BUILD_DIR [--rounds N] [--seconds S]
"""

import argparse
import os
import re
import shutil
import statistics
import subprocess

# The columns: roscpp is the reference, genmros the heap storage every ROS
# build gets, bounded genmros' heap-free storage, memcpy the floor for large
# payloads (a bare copy of the same wire image).
SIDES = ['roscpp', 'genmros', 'bounded', 'memcpy']
OPERATIONS = ['encode', 'decode']
CODE_LAYOUTS = 4


def heap_shift(round_number):
    """Bytes allocated before measuring in a round: multiples of 16 (malloc's
    alignment) spread over a page, the same for every side of the round."""
    return 16 * ((round_number * 37) % 256)


def executable(build_dir, side, round_number):
    """The side's build in the round's code layout."""
    return os.path.join(build_dir, 'bench_%s.%d' % (side, round_number % CODE_LAYOUTS))


def measure(build_dir, side, instance, operation, seconds, round_number):
    command = [executable(build_dir, side, round_number), 'time', str(instance), operation,
               str(seconds), str(heap_shift(round_number))]
    output = subprocess.run(command, capture_output=True, text=True, check=True).stdout.split()
    return int(output[0]), float(output[1])


def instructions_per_call(build_dir, side, instance, operation, calls=20):
    def collected(count):
        run = subprocess.run(['valgrind', '--tool=callgrind', '--callgrind-out-file=/dev/null',
                              executable(build_dir, side, 0), 'repeat', str(instance), operation,
                              str(count)],
                             capture_output=True, text=True, check=True)
        return int(re.search(r'Collected : (\d+)', run.stderr).group(1))
    return (collected(2 * calls) - collected(calls)) / calls


def instances(build_dir):
    listing = subprocess.run([executable(build_dir, 'genmros', 0), 'list'],
                             capture_output=True, text=True, check=True).stdout
    return [(name, large == '1')
            for name, large in (line.split('\t') for line in listing.splitlines())]


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
    built = [s for s in SIDES if os.path.exists(executable(arguments.build_dir, s, 0))]

    rows = []
    for index, (name, large) in enumerate(instances(arguments.build_dir)):
        sides = [s for s in built if s != 'memcpy' or large]
        for operation in OPERATIONS:
            rounds = []
            for round_number in range(arguments.rounds):
                order = sides[round_number % len(sides):] + sides[:round_number % len(sides)]
                times = {}
                for side in order:
                    size, times[side] = measure(arguments.build_dir, side, index, operation,
                                                arguments.seconds, round_number)
                rounds.append(times)
            rows.append((name, operation, size, sides, rounds))

    print('Median ns per call over %d rounds (each a fresh process per side: warm-up, '
          'then the median of 15 batches; every side of a round in the same code layout '
          'and heap shift, another each round); '
          'speed ratios are roscpp time / genmros time, median (min-max) of the rounds.'
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

    if shutil.which('valgrind'):
        print_instruction_table(arguments.build_dir, [(
            name, sides) for name, _, _, sides, _ in rows[::2]])


def print_instruction_table(build_dir, instance_sides):
    print()
    print('Instructions per call (callgrind); ratios are roscpp instructions / the column\'s.')
    print()
    print('| message | op | roscpp | genmros | genmros vs roscpp | bounded | bounded vs roscpp |')
    print('|---|---|---:|---:|---:|---:|---:|')
    for index, (name, sides) in enumerate(instance_sides):
        for operation in OPERATIONS:
            counts = {side: instructions_per_call(build_dir, side, index, operation)
                      for side in ('roscpp', 'genmros', 'bounded') if side in sides}
            cells = [name, operation]
            for side in ('roscpp', 'genmros', 'bounded'):
                if side not in counts:
                    cells += ['-'] * (1 if side == 'roscpp' else 2)
                    continue
                cells.append('%.0f' % counts[side])
                if side != 'roscpp':
                    cells.append('%.2fx' % (counts['roscpp'] / counts[side]))
            print('| ' + ' | '.join(cells) + ' |')


if __name__ == '__main__':
    main()
