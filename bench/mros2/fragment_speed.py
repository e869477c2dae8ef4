#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""How long mros2 takes to publish a large message in fragments, beside copyToBuf.

    /usr/bin/python3 bench/mros2/fragment_speed.py [--kb 1,4,16,64,256,1024]
        [--baseline REV] [--callgrind] [--qemu-arm] [--rounds N] [--seconds S] [--keep DIR]

mros2 publishes a sample larger than its 100-byte buffer through calls of
copyToFragBuf into a 64-byte fragment buffer (the first fragment holds the
encapsulation header and 60 bytes of the image), until one returns
{true, 0}. The types, exported here with genmros from a scratch ROS 2
package (frag_bench), each filled to about 1 KB .. 1 MB of image:

- Items: ``Item[] items``, an Item ``int32 id, float64 value, string name``;
- Numbers: ``float64[] data, uint8[] blob, string label`` (blob 4 bytes per datum);
- Groups: ``Items[] groups`` of 16 Items each: sequences nested two deep.

One C++ program (fragment_speed.cpp beside this script, g++ -O2 on the
host) checks that the fragments carry copyToBuf's image, header and padding
included, twice, then times one copyToBuf and all the copyToFragBuf calls
of one publication (the median of --rounds loops of about --seconds; a call
of --seconds or more is timed once). Columns: the image's bytes; both
times; their ratio; the ns each fragment costs beyond copyToBuf (all
fragments minus copyToBuf, over the calls); the bytes that keep where the
last fragment stopped (4 per nesting level and 4: idxSerialized of the
message and of a nested message per level, and cntSub, counters every
mros2 message has anyway), and sizeof the message (before and after with
--baseline: the state takes no room of its own).

--baseline REV also exports the types with genmros as it is at git
revision REV (e.g. main) and times that build beside, in the same run.
--callgrind counts, under valgrind's callgrind, the instructions of one
copyToBuf and of one fragmented publication, and prints the instructions
per fragment beyond copyToBuf: flat in the image's size when each fragment
continues where the last stopped. --qemu-arm builds the program with
arm-linux-gnueabihf-g++ -static and times it under qemu-arm instead
(emulated time: the ratios are what tells).
"""

import argparse
import os
import re
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, REPO)  # colcon_mros and the shared testing package
from testing.interface_packages import write_interface_package  # noqa: E402

SOURCE = os.path.join(HERE, 'fragment_speed.cpp')
TYPES = ('Items', 'Numbers', 'Groups')

MESSAGES = {
    'Item': 'int32 id\nfloat64 value\nstring name\n',
    'Items': 'Item[] items\n',
    'Numbers': 'float64[] data\nuint8[] blob\nstring label\n',
    'Groups': 'Items[] groups\n',
}


def _workspace(root):
    return write_interface_package(os.path.join(root, 'ws'), 'frag_bench', MESSAGES,
                                   'Messages of bench/mros2/fragment_speed.py.')


def _export(genmros_root, workspace, include_dir):
    """The headers as the genmros at genmros_root (a colcon_mros checkout) writes them."""
    subprocess.run(['/usr/bin/python3', '-m', 'colcon_mros', 'mros2-export', '--workspace',
                    workspace, '-o', include_dir]
                   + ['--type=frag_bench/msg/%s' % name for name in TYPES],
                   check=True, stdout=subprocess.DEVNULL,
                   env=dict(os.environ, PYTHONPATH=genmros_root), cwd=genmros_root)


def _baseline(revision, root):
    """colcon_mros as it is at git revision, unpacked under root."""
    target = os.path.join(root, 'baseline')
    os.makedirs(target)
    archive = subprocess.run(['git', '-C', REPO, 'archive', revision, 'colcon_mros'],
                             check=True, capture_output=True).stdout
    subprocess.run(['tar', '-x', '-C', target], input=archive, check=True)
    return target


def _nesting_depth(message):
    """How deep messages nest in message, itself included."""
    return 1 + max((_nesting_depth(member.message) for member in message.members
                    if member.element == 'message'), default=0)


def _state_bytes(workspace):
    """The bytes that keep where a fragment stopped, per type: idxSerialized
    of the message and of the nested message at each level, and cntSub."""
    from colcon_mros.core.storage import HeapStorage
    from colcon_mros.ros2.interfaces import all_packages
    from colcon_mros.ros2.model import ModelBuilder
    builder = ModelBuilder(all_packages([workspace], []), HeapStorage())
    return {name: 4 * (_nesting_depth(builder.message('frag_bench/msg/' + name)) + 1)
            for name in TYPES}


def _build(include_dir, program, qemu_arm):
    compiler = ['arm-linux-gnueabihf-g++', '-static'] if qemu_arm else ['g++']
    subprocess.run(compiler + ['-std=c++11', '-O2', '-g', '-Wall', '-Wextra', '-pedantic',
                               '-I', include_dir, SOURCE, '-o', program], check=True)
    return (['qemu-arm', program] if qemu_arm else [program])


def _time(command, args):
    output = subprocess.run(command + ['time', str(args.seconds), str(args.rounds)]
                            + [str(kb) for kb in args.kb], check=True, capture_output=True,
                            text=True).stdout
    rows = {}
    for line in output.splitlines():
        name, kb, size, whole, fragments, calls, size_of = line.split()
        rows[name, int(kb)] = (int(size), float(whole), float(fragments), int(calls),
                               int(size_of))
    return rows


def _instructions(command, name, kb, what, scratch):
    out = os.path.join(scratch, 'callgrind.%s.%d.%s' % (name, kb, what))
    function = 'measure_whole' if what == 'whole' else 'measure_fragments'
    result = subprocess.run(['valgrind', '--tool=callgrind', '--callgrind-out-file=' + out,
                             '--toggle-collect=*%s*' % function] + command
                            + ['once', name, str(kb), what], check=True, capture_output=True,
                            text=True)
    calls = int(result.stdout) if what == 'fragments' else 0
    with open(out) as stream:
        total = int(re.search(r'^summary: (\d+)', stream.read(), re.M).group(1))
    return total, calls


def _us(ns):
    us = ns / 1000
    return '%.0f' % us if us >= 100 else '%.2f' % us if us < 10 else '%.1f' % us


def _print_times(title, rows, state, args, baseline_rows=None):
    print('\n' + title)
    header = ['type', 'KB', 'image bytes']
    if baseline_rows:
        header += ['before: copyToBuf µs', 'before: all fragments µs', 'before: ratio']
    header += ['copyToBuf µs', 'all fragments µs', 'ratio', 'fragments',
               'ns per fragment beyond copyToBuf', 'state bytes', 'sizeof']
    print('| ' + ' | '.join(header) + ' |')
    print('|---|' + '---:|' * (len(header) - 1))
    for name in TYPES:
        for kb in args.kb:
            size, whole, fragments, calls, size_of = rows[name, kb]
            cells = [name, str(kb), str(size)]
            if baseline_rows:
                _, b_whole, b_fragments, _, b_size_of = baseline_rows[name, kb]
                cells += [_us(b_whole), _us(b_fragments), '%.0fx' % (b_fragments / b_whole)]
                size_of = '%d (before %d)' % (size_of, b_size_of)
            cells += [_us(whole), _us(fragments), '%.1fx' % (fragments / whole), str(calls),
                      '%.1f' % ((fragments - whole) / calls), str(state[name]), str(size_of)]
            print('| ' + ' | '.join(cells) + ' |')


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('--kb', type=lambda text: [int(kb) for kb in text.split(',')],
                        default=[1, 4, 16, 64, 256, 1024], help='image sizes, comma-separated')
    parser.add_argument('--baseline', metavar='REV',
                        help='also time genmros as it is at this git revision')
    parser.add_argument('--callgrind', action='store_true',
                        help='instructions per fragment under callgrind (needs valgrind)')
    parser.add_argument('--qemu-arm', action='store_true',
                        help='build for 32-bit ARM Linux, run under qemu-arm')
    parser.add_argument('--rounds', type=int, default=5)
    parser.add_argument('--seconds', type=float, default=0.1, help='per timed loop')
    parser.add_argument('--keep', help='write the export and the programs here and keep them')
    args = parser.parse_args()
    for tool in (['arm-linux-gnueabihf-g++', 'qemu-arm'] if args.qemu_arm else ['g++']) + (
            ['valgrind'] if args.callgrind else []):
        if shutil.which(tool) is None:
            print('%s: needs %s' % (sys.argv[0], tool), file=sys.stderr)
            return 2

    with tempfile.TemporaryDirectory(prefix='fragment_speed_') as scratch:
        work = args.keep or scratch
        os.makedirs(work, exist_ok=True)
        workspace = _workspace(work)
        include_dir = os.path.join(work, 'include')
        _export(REPO, workspace, include_dir)
        state = _state_bytes(workspace)
        command = _build(include_dir, os.path.join(work, 'fragment_speed'), args.qemu_arm)
        baseline_command = None
        if args.baseline:
            baseline_include = os.path.join(work, 'include_baseline')
            _export(_baseline(args.baseline, work), workspace, baseline_include)
            baseline_command = _build(baseline_include,
                                      os.path.join(work, 'fragment_speed_baseline'),
                                      args.qemu_arm)
        target = ('arm-linux-gnueabihf-g++ -static -O2 under qemu-arm' if args.qemu_arm
                  else 'g++ -O2 on the host')
        baseline_rows = _time(baseline_command, args) if baseline_command else None
        rows = _time(command, args)
        _print_times('One publication in 64-byte fragments (60 bytes of image in the first), '
                     'beside one copyToBuf; %s, median of %d loops of ~%.2f s%s'
                     % (target, args.rounds, args.seconds,
                        '; before: genmros at %s' % args.baseline if args.baseline else ''),
                     rows, state, args, baseline_rows)

        if args.callgrind:
            print('\nInstructions under callgrind (%s): one copyToBuf, one publication in '
                  'fragments' % target)
            print('| type | KB | copyToBuf | all fragments | fragments '
                  '| per fragment beyond copyToBuf |')
            print('|---|---:|---:|---:|---:|---:|')
            for name in TYPES:
                for kb in args.kb:
                    whole, _ = _instructions(command, name, kb, 'whole', work)
                    fragments, calls = _instructions(command, name, kb, 'fragments', work)
                    print('| %s | %d | %d | %d | %d | %.0f |' % (
                        name, kb, whole, fragments, calls, (fragments - whole) / calls))
    return 0


if __name__ == '__main__':
    sys.exit(main())
