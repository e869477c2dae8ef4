#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""How fast genmros generates, side by side with gencpp in one run.

    /usr/bin/python3 bench/export_speed.py [--rounds N] [--empy4-python PYTHON]

For the 15 Debian message packages: one `genmros mros-v1-export` of all of them
(every header, the support header and the aggregates), against Debian's
gencpp run once per .msg/.srv file, as catkin runs it; and the same export
with every template run by empy's Interpreter (none compiled: what a user's
template directory with more than logic-free markup costs). With
--empy4-python (a venv's python over Debian's with empy 4: tests/conftest.py
makes one) both exports again under empy 4. Also the time of
`genmros --version` (the interpreter and genmros' start-up) and of the
imports a generator run makes. Prints medians of --rounds rounds, the sides
taking turns, and their ratio.
"""

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, REPO)  # the shared testing package

from testing import ros_paths  # noqa: E402

PACKAGES = ['std_msgs', 'geometry_msgs', 'sensor_msgs', 'nav_msgs', 'trajectory_msgs',
            'visualization_msgs', 'diagnostic_msgs', 'actionlib_msgs', 'shape_msgs',
            'stereo_msgs', 'tf2_msgs', 'map_msgs', 'pcl_msgs', 'std_srvs', 'rosgraph_msgs']
GENMROS = ['/usr/bin/python3', '-m', 'colcon_mros']
# genmros with no template compiled (colcon_mros.core.render).
INTERPRETER_ONLY = ('import sys\n'
                    'from colcon_mros import cli\n'
                    'from colcon_mros.core import render\n'
                    'render.compiled_template = lambda path: None\n'
                    'sys.exit(cli.main(sys.argv[1:]))\n')
ENVIRONMENT = dict(os.environ, PYTHONPATH=REPO)


def _definitions():
    found = []
    for package in PACKAGES:
        for kind in ('msg', 'srv'):
            found += [(package, path) for path in ros_paths.ros1_definitions(package, kind)]
    return found


def _timed(commands):
    start = time.perf_counter()
    for command in commands:
        subprocess.run(command, check=True, stdout=subprocess.DEVNULL, env=ENVIRONMENT)
    return time.perf_counter() - start


def _empy_version(python):
    return subprocess.run([python, '-c', 'import em; print(em.__version__)'], check=True,
                          capture_output=True, text=True).stdout.strip()


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('--rounds', type=int, default=3)
    parser.add_argument('--empy4-python', help='a python with empy 4 and genmsg')
    args = parser.parse_args()
    pythons = [GENMROS[0]] + ([args.empy4_python] if args.empy4_python else [])
    definitions = _definitions()
    includes = []
    for package in sorted({package for package, _ in definitions} | {'std_msgs', 'geometry_msgs'}):
        includes += ['-I', '%s:%s' % (package, ros_paths.ros1_package_dir(package))]
    gen_cpp, templates = ros_paths.gencpp()
    exports = {}
    with tempfile.TemporaryDirectory(prefix='export_speed_') as scratch:
        export = ['mros-v1-export', *ros_paths.prefix_arguments(ros_paths.ros1_prefixes()),
                  '-o', os.path.join(scratch, 'mros')]
        for package in PACKAGES:
            export += ['--package', package]
        for python in pythons:
            empy = 'empy %s' % _empy_version(python)
            exports['genmros mros-v1-export, all 15 packages in one process (%s)' % empy] = \
                [python, '-m', 'colcon_mros'] + export
            exports['the same, every template through empy\'s Interpreter (%s)' % empy] = \
                [python, '-c', INTERPRETER_ONLY] + export
        gencpp = [['/usr/bin/python3', gen_cpp, path, '-p', package,
                   '-o', os.path.join(scratch, 'gencpp', package), '-e', templates] + includes
                  for package, path in definitions]
        samples = {'gencpp': [], 'version': [], **{run: [] for run in exports}}
        for _ in range(args.rounds):
            for run, command in exports.items():
                samples[run].append(_timed([command]))
            samples['gencpp'].append(_timed(gencpp))
            samples['version'].append(_timed([GENMROS + ['--version']]))
    imports = subprocess.run(GENMROS[:1] + ['-X', 'importtime', '-c',
                                            'import colcon_mros.export.firmware_export'],
                             env=ENVIRONMENT, capture_output=True, text=True).stderr
    cumulative = [line.split('|') for line in imports.splitlines() if '|' in line]
    total_us = max(int(fields[1]) for fields in cumulative[1:])
    gencpp = statistics.median(samples['gencpp'])
    print('\n%d definitions of the 15 Debian message packages, median of %d rounds'
          % (len(definitions), args.rounds))
    print('| run | seconds | gencpp / it |')
    print('|---|---:|---:|')
    print('| gencpp, one process per file (as catkin runs it) | %.2f | 1.0x |' % gencpp)
    for run in exports:
        seconds = statistics.median(samples[run])
        print('| %s | %.2f | %.1fx |' % (run, seconds, gencpp / seconds))
    print('| genmros --version (interpreter and start-up) | %.3f | |'
          % statistics.median(samples['version']))
    print('| imports of an export run (python -X importtime) | %.3f | |' % (total_us / 1e6))
    return 0


if __name__ == '__main__':
    sys.exit(main())
