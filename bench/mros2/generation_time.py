#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""How fast genmros generates mros2 headers, side by side with mros2's own generator.

    MROS2_ROOT=<mros2 checkout> /usr/bin/python3 bench/mros2/generation_time.py [--rounds N]

On the types mros2's Jinja2 generator (MROS2_ROOT/mros2_header_generator)
handles: the five geometry_msgs .msg files mros2 ships in
mros2_msgs/geometry_msgs/msg (Point, Pose, Quaternion, Twist, Vector3) and
std_msgs/String (ROS 2's definition, `string data`). Times, median of
--rounds rounds, the three runs taking turns:

- mros2's generator as its users run it: one cold process per .msg file
  (`python3 header_generator.py pkg/msg/Type.msg` from a directory holding
  the .msg files in the pkg/msg layout it expects; it writes pkg/msg/type.hpp
  there and regenerates the headers of the types a type contains);
- genmros, one process per type (`genmros mros2-export --workspace WS --type T`);
- genmros, one process for all six.

Then whether each header compiles (g++ -std=c++14 -fsyntax-only): alone, and
after mros2.h (the runtime stand-in's, testing/mros2_runtime), as an mros2
application includes it. mros2's generator needs jinja2 (Debian python3-jinja2).
"""

import argparse
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
RUNTIME = os.path.join(REPO, 'testing', 'mros2_runtime')
GENMROS = ['/usr/bin/python3', '-m', 'colcon_mros']
ENVIRONMENT = dict(os.environ, PYTHONPATH=REPO)
GEOMETRY = ['Point', 'Pose', 'Quaternion', 'Twist', 'Vector3']
# (package, type, header stem)
TYPES = [('geometry_msgs', name, name.lower()) for name in GEOMETRY] + [
    ('std_msgs', 'String', 'string')]


def _write_sources(mros2_root, root, ros2):
    """The .msg files in the pkg/msg layout, each package with a package.xml.
    mros2's generator finds a nested type as the file pkg/msg/Type.msg from
    the type name written pkg/msg/Type, as mros2's .msg files write it; ROS 2
    (rosidl, so genmros) takes pkg/Type and refuses pkg/msg/Type: with ros2,
    the same files with the names as ROS 2 writes them."""
    sys.path.insert(0, REPO)
    from testing.ros2_messages import PACKAGE_XML
    for package in ('geometry_msgs', 'std_msgs'):
        os.makedirs(os.path.join(root, package, 'msg'))
        with open(os.path.join(root, package, 'package.xml'), 'w') as stream:
            stream.write(PACKAGE_XML % package)
    for name in GEOMETRY:
        with open(os.path.join(mros2_root, 'mros2_msgs', 'geometry_msgs', 'msg', name + '.msg')) \
                as stream:
            text = stream.read()
        if ros2:
            text = re.sub(r'\b(\w+)/msg/(\w+)', r'\1/\2', text)
        with open(os.path.join(root, 'geometry_msgs', 'msg', name + '.msg'), 'w') as stream:
            stream.write(text)
    with open(os.path.join(root, 'std_msgs', 'msg', 'String.msg'), 'w') as stream:
        stream.write('string data\n')


def _timed(commands, cwd=None):
    start = time.perf_counter()
    for command in commands:
        subprocess.run(command, check=True, cwd=cwd, stdout=subprocess.DEVNULL,
                       stderr=subprocess.DEVNULL, env=ENVIRONMENT)
    return time.perf_counter() - start


def _fresh(sources, directory):
    shutil.rmtree(directory, ignore_errors=True)
    shutil.copytree(sources, directory)
    return directory


def _compiles(include_dir, header, after_mros2_h, scratch):
    source = os.path.join(scratch, 'check.cpp')
    with open(source, 'w') as stream:
        if after_mros2_h:
            stream.write('#include "mros2.h"\n')
        stream.write('#include "%s"\n' % header)
    result = subprocess.run(['g++', '-std=c++14', '-fsyntax-only', '-I', include_dir,
                             '-I', RUNTIME, source], capture_output=True, text=True)
    if result.returncode == 0:
        return 'yes', ''
    error = next((line for line in result.stderr.splitlines() if 'error' in line), '')
    return 'no', error.replace(include_dir + '/', '')


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('--rounds', type=int, default=5)
    args = parser.parse_args()
    mros2_root = os.environ.get('MROS2_ROOT', '')
    generator = os.path.join(mros2_root, 'mros2_header_generator', 'header_generator.py')
    if not os.path.isfile(generator):
        print('%s: needs an mros2 checkout (its mros2_header_generator): set MROS2_ROOT'
              % sys.argv[0], file=sys.stderr)
        return 2
    if subprocess.run(['/usr/bin/python3', '-c', 'import jinja2']).returncode != 0:
        print('%s: mros2\'s generator needs jinja2 for /usr/bin/python3 (Debian python3-jinja2)'
              % sys.argv[0], file=sys.stderr)
        return 2
    samples = {'mros2': [], 'genmros_each': [], 'genmros_all': []}
    failed = {}
    with tempfile.TemporaryDirectory(prefix='generation_time_') as scratch:
        sources, ros2_sources = os.path.join(scratch, 'sources'), os.path.join(scratch, 'ros2')
        _write_sources(mros2_root, sources, ros2=False)
        _write_sources(mros2_root, ros2_sources, ros2=True)
        names = ['%s/msg/%s' % (package, name) for package, name, _ in TYPES]
        mros2_dir = os.path.join(scratch, 'mros2')
        each_dir, all_dir = os.path.join(scratch, 'each'), os.path.join(scratch, 'all')
        for _ in range(args.rounds):
            _fresh(sources, mros2_dir)
            start = time.perf_counter()
            for name in names:  # one at a time, as users run it; note any failure
                result = subprocess.run(['/usr/bin/python3', generator, name + '.msg'],
                                        cwd=mros2_dir, capture_output=True, text=True)
                if result.returncode != 0 or 'not found' in result.stdout:
                    failed[name] = (result.stdout + result.stderr).strip().splitlines()[-1]
            samples['mros2'].append(time.perf_counter() - start)
            shutil.rmtree(each_dir, ignore_errors=True)
            samples['genmros_each'].append(_timed(
                [GENMROS + ['mros2-export', '--workspace', ros2_sources, '--type', name,
                            '-o', each_dir]
                 for name in names]))
            shutil.rmtree(all_dir, ignore_errors=True)
            samples['genmros_all'].append(_timed(
                [GENMROS + ['mros2-export', '--workspace', ros2_sources, '-o', all_dir]
                 + ['--type=%s' % name for name in names]]))
        compiled = []
        for package, name, stem in TYPES:
            header = '%s/msg/%s.hpp' % (package, stem)
            row = [package + '/msg/' + name]
            for include_dir in (mros2_dir, all_dir):
                if not os.path.isfile(os.path.join(include_dir, header)):
                    row += ['no header', 'no header', '']
                    continue
                alone, error = _compiles(include_dir, header, False, scratch)
                after, error_after = _compiles(include_dir, header, True, scratch)
                row += [alone, after, error or error_after]
            compiled.append(row)

    mros2, each, together = (statistics.median(samples[key])
                             for key in ('mros2', 'genmros_each', 'genmros_all'))
    print('\nHeaders of the 5 geometry_msgs types mros2 ships as .msg and std_msgs/String, '
          'seconds, median of %d rounds' % args.rounds)
    print('| run | seconds | mros2\'s generator / it |')
    print('|---|---:|---:|')
    print('| mros2\'s header_generator.py, one process per .msg (as its users run it) '
          '| %.2f | 1.0x |' % mros2)
    print('| genmros mros2-export, one process per type | %.2f | %.2fx |' % (each, mros2 / each))
    print('| genmros mros2-export, one process for all 6 | %.2f | %.2fx |'
          % (together, mros2 / together))
    print('\nDoes the header compile (g++ -std=c++14 -fsyntax-only)? Alone, and after mros2.h '
          '(the runtime stand-in\'s), as an application includes it')
    print('| type | mros2\'s generator: alone | after mros2.h | genmros: alone | after mros2.h '
          '| first error (alone) |')
    print('|---|---|---|---|---|---|')
    for row in compiled:
        errors = '; '.join(e for e in (row[3], row[6]) if e)
        print('| %s | %s | %s | %s | %s | %s |' % (row[0], row[1], row[2], row[4], row[5],
                                                   ('`%s`' % errors) if errors else ''))
    for name, error in sorted(failed.items()):
        print('\nmros2\'s generator failed on %s: %s' % (name, error))
    return 0


if __name__ == '__main__':
    sys.exit(main())
