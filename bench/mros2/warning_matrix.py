#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""The whole warning matrix of the mros2 headers, by hand.

    /usr/bin/python3 bench/mros2/warning_matrix.py [--jobs 2] [--keep DIR]

builds the caller of testing/mros2_warning_matrix.py (every message type of
test_ws_ros2 and of ROS 2's test interface files, and the type the
warning was first found with, published in fragments as mros2's publish sends
them, in one translation unit) with {g++, arm-none-eabi-g++ (compiled
only), clang++} x {-O0, -O1, -O2, -O3, -Os} x {C++11, 14, 17, 20} and
-Wall -Wextra -Wpedantic -Wconversion -Wsign-conversion -Werror, runs each
host program's byte check, and prints a table: the warnings of each
configuration, and the byte checks' failures. Exits 1 if a configuration
warned, failed to compile or failed its byte check.
tests/mros2/test_warning_matrix.py runs a part of it.
"""

import argparse
import os
import shutil
import sys
import tempfile
import time
from concurrent.futures import ThreadPoolExecutor

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, REPO)  # the shared testing package

from testing import mros2_warning_matrix as matrix  # noqa: E402


def _check_bytes(build):
    """A host build's byte check: its failures, or None for an object or a failed build."""
    if build.output is None or build.configuration.compiler in matrix.COMPILE_ONLY:
        return None
    return matrix.run(build.output)[2]


def _cell(build, failures):
    """One configuration in the table: its warnings, then what else went wrong."""
    text = str(len(build.warnings))
    if build.errors:
        text += ' (%d errors)' % build.errors
    if failures:
        text += ' (%d bytes differ)' % failures
    return text


def print_table(builds, failures):
    """Rows compiler and level, columns standards, cells warnings."""
    by_configuration = {build.configuration: build for build in builds}
    print('| compiler | level | ' + ' | '.join(matrix.STANDARDS) + ' |')
    print('|---|---|' + '---:|' * len(matrix.STANDARDS))
    for compiler in matrix.COMPILERS:
        for level in matrix.LEVELS:
            cells = [_cell(by_configuration[configuration], failures[configuration])
                     for configuration in (matrix.Configuration(compiler, level, standard)
                                           for standard in matrix.STANDARDS)]
            print('| %s | %s | %s |' % (compiler, level, ' | '.join(cells)))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('--jobs', type=int, default=2, help='compilers run at once')
    parser.add_argument('--keep', help='build here and keep it')
    args = parser.parse_args()
    for compiler in matrix.COMPILERS.values():
        if shutil.which(compiler[0]) is None:
            print('%s: needs %s' % (sys.argv[0], compiler[0]), file=sys.stderr)
            return 2

    with tempfile.TemporaryDirectory(prefix='warning_matrix_') as scratch:
        work = args.keep or scratch
        os.makedirs(work, exist_ok=True)
        include_dir = matrix.export_headers(os.path.join(work, 'include'))
        types = matrix.message_types(include_dir)
        source = matrix.write_program(types, os.path.join(work, 'fragment_caller.cpp'))
        configurations = matrix.every_configuration()
        started = time.time()
        with ThreadPoolExecutor(max_workers=args.jobs) as pool:
            builds = list(pool.map(lambda configuration: matrix.build(
                configuration, include_dir, source, work), configurations))
        failures = {build.configuration: _check_bytes(build) for build in builds}
        seconds = time.time() - started

    print('Warnings of each configuration (%s): %d types in one translation unit, fragment '
          'buffers of %s bytes; %d configurations in %.0f s, %d at a time'
          % (' '.join(matrix.WARNING_FLAGS), len(types),
             ', '.join(str(size) for size in matrix.FRAGMENT_BUFFER_SIZES),
             len(builds), seconds, args.jobs))
    print_table(builds, failures)
    warnings = sum(len(build.warnings) for build in builds)
    checked = [count for count in failures.values() if count is not None]
    print('\n%d configurations, %d warnings, %d failed builds; %d host programs ran their '
          'byte check, %d failures' % (
              len(builds), warnings, len([build for build in builds if build.output is None]),
              len(checked), sum(checked)))
    for build in builds:
        if build.warnings or build.errors or build.output is None:
            print('\n%s:\n%s' % (' '.join(build.configuration), build.stderr[-3000:]))
    return 0 if warnings == 0 and sum(checked) == 0 and all(
        build.output for build in builds) else 1


if __name__ == '__main__':
    sys.exit(main())
