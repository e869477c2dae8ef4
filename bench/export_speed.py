#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""How fast genmros generates, side by side with gencpp in one run.

    /usr/bin/python3 bench/export_speed.py [--rounds N]

For the 15 Debian message packages: one `genmros mros-v1-export` of all of them
(every header, the support header and the aggregates), against Debian's
gencpp run once per .msg/.srv file, as catkin runs it. Also the time of
`genmros --version` (the interpreter and genmros' start-up) and of the
imports a generator run makes. Prints medians of --rounds rounds, the two
sides taking turns, and their ratio.
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


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('--rounds', type=int, default=3)
    args = parser.parse_args()
    definitions = _definitions()
    includes = []
    for package in sorted({package for package, _ in definitions} | {'std_msgs', 'geometry_msgs'}):
        includes += ['-I', '%s:%s' % (package, ros_paths.ros1_package_dir(package))]
    gen_cpp, templates = ros_paths.gencpp()
    samples = {'genmros': [], 'gencpp': [], 'version': []}
    with tempfile.TemporaryDirectory(prefix='export_speed_') as scratch:
        export = GENMROS + ['mros-v1-export',
                            *ros_paths.prefix_arguments(ros_paths.ros1_prefixes()),
                            '-o', os.path.join(scratch, 'mros')]
        for package in PACKAGES:
            export += ['--package', package]
        gencpp = [['/usr/bin/python3', gen_cpp, path, '-p', package,
                   '-o', os.path.join(scratch, 'gencpp', package), '-e', templates] + includes
                  for package, path in definitions]
        for _ in range(args.rounds):
            samples['genmros'].append(_timed([export]))
            samples['gencpp'].append(_timed(gencpp))
            samples['version'].append(_timed([GENMROS + ['--version']]))
    imports = subprocess.run(GENMROS[:1] + ['-X', 'importtime', '-c',
                                            'import colcon_mros.export.firmware_export'],
                             env=ENVIRONMENT, capture_output=True, text=True).stderr
    cumulative = [line.split('|') for line in imports.splitlines() if '|' in line]
    total_us = max(int(fields[1]) for fields in cumulative[1:])
    genmros, gencpp = (statistics.median(samples[key]) for key in ('genmros', 'gencpp'))
    print('\n%d definitions of the 15 Debian message packages, median of %d rounds'
          % (len(definitions), args.rounds))
    print('| run | seconds | gencpp / it |')
    print('|---|---:|---:|')
    print('| gencpp, one process per file (as catkin runs it) | %.2f | 1.0x |' % gencpp)
    print('| genmros mros-v1-export, all 15 packages in one process | %.2f | %.1fx |'
          % (genmros, gencpp / genmros))
    print('| genmros --version (interpreter and start-up) | %.3f | |'
          % statistics.median(samples['version']))
    print('| imports of an export run (python -X importtime) | %.3f | |' % (total_us / 1e6))
    return 0


if __name__ == '__main__':
    sys.exit(main())
