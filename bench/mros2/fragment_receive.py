#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""What the patch data-frag-for-best-effort-readers costs a board: receive time and RAM.

    MROS2_ROOT=... /usr/bin/python3 bench/mros2/fragment_receive.py [--keep DIR]

Builds embeddedRTPS' real MessageReceiver from a copy of MROS2_ROOT (as it is, and with the
patch alone) with the stand-in entities of testing/mros2_library/receiver and
fragment_receive.cpp beside this script.

Receive time (g++ -O2, this PC): one sample of 65000 bytes (an Image of 64 KB; the config's
FRAGMENT_BUFFER_SIZE 65000, one buffer) given to the receiver as one DATA datagram (a
receive limit of 65535 allows it), as DATA_FRAGs of 3920 bytes (what Fast DDS 3 sends under
a maxMessageSize of 4096) and of 1296 (under 1472), side by side in one run: the median
over 2001 samples of the time from the first datagram to the sample's delivery, and the
ratio to one datagram.

RAM: sizeof(rtps::MessageReceiver), which a participant holds (static in mros2's Domain),
as it is and patched, for several settings, on this PC (x86-64) and on 32-bit ARM
(arm-linux-gnueabihf-g++ -static, run under qemu-arm: a Cortex-M's ABI has the same sizes
and alignments for these members).
"""

import argparse
import os
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, REPO)  # colcon_mros and the shared testing package
from colcon_mros.library_tools.mros2.patches import mros2_patches  # noqa: E402
from colcon_mros.library_tools.mros2.pc_target.build import TARGET_DIR  # noqa: E402
from colcon_mros.library_tools.patch_series import apply_patches  # noqa: E402
from testing.rtps_datagrams import data, data_frag, rtps_header  # noqa: E402

PATCH = 'data-frag-for-best-effort-readers'
STAND_IN = os.path.join(REPO, 'testing', 'mros2_library', 'receiver')
SAMPLE = 65000
READER, WRITER = bytes([0, 0, 1, 4]), bytes([0, 0, 1, 3])
# (what, fragment size or None for one DATA)
CASES = (('one DATA (receive limit 65535)', None),
         ('DATA_FRAG of 3920 (limit 4096)', 3920),
         ('DATA_FRAG of 1296 (limit 1472)', 1296))
# (settings, -D flags): None is the library as it is.
RAM_SETTINGS = (('as it is', None), ('patched, no settings (0 bytes, 1 buffer)', ()),
                ('FRAGMENT_BUFFER_SIZE 1024', (1024, 1)),
                ('FRAGMENT_BUFFER_SIZE 4096', (4096, 1)),
                ('FRAGMENT_BUFFER_SIZE 20000', (20000, 1)),
                ('FRAGMENT_BUFFER_SIZE 65000', (65000, 1)),
                ('FRAGMENT_BUFFER_SIZE 65000, FRAGMENT_BUFFERS 2', (65000, 2)))


def checkout(work, patched):
    root = os.path.join(work, 'patched' if patched else 'as_it_is')
    if not os.path.isdir(root):
        shutil.copytree(os.path.join(os.environ['MROS2_ROOT'], 'embeddedRTPS'),
                        os.path.join(root, 'embeddedRTPS'))
        for part in ('include', 'src'):
            shutil.copytree(os.path.join(os.environ['MROS2_ROOT'], part),
                            os.path.join(root, part))
        if patched:
            apply_patches(root, [p for p in mros2_patches() if p.name == PATCH])
    return root


def build(work, root, name, settings, arm=False):
    program = os.path.join(work, name)
    # -Wno-psabi: GCC's note that its ARM ABI for std::vector iterators changed in GCC 7.1
    compiler = ['arm-linux-gnueabihf-g++', '-static', '-Wno-psabi'] if arm else ['g++']
    command = compiler + ['-std=gnu++14', '-O2', '-I', STAND_IN, '-I',
                          os.path.join(TARGET_DIR, 'include'),
                          '-I', os.path.join(root, 'embeddedRTPS', 'include')]
    if settings:
        command += ['-DRECEIVER_CHECK_BUFFER_SIZE=%d' % settings[0],
                    '-DRECEIVER_CHECK_BUFFERS=%d' % settings[1]]
    command += [os.path.join(root, 'embeddedRTPS', 'src', 'messages', source)
                for source in ('MessageReceiver.cpp', 'MessageTypes.cpp')]
    command += [os.path.join(HERE, 'fragment_receive.cpp'), '-o', program]
    subprocess.run(command, check=True)
    return ['qemu-arm', program] if arm else [program]


def sample_datagrams(fragment):
    sample = bytes([0, 1, 0, 0]) + bytes(index % 251 for index in range(SAMPLE - 4))
    if fragment is None:
        return [rtps_header(bytes([0x11] * 12)) + data(READER, WRITER, 1, sample).encode()]
    return [rtps_header(bytes([0x11] * 12)) + data_frag(
        READER, WRITER, 1, number + 1, fragment, SAMPLE,
        sample[number * fragment:(number + 1) * fragment]).encode()
        for number in range(-(-SAMPLE // fragment))]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('--keep', metavar='DIR', help='build there and keep it')
    options = parser.parse_args()
    if not os.environ.get('MROS2_ROOT'):
        print('fragment_receive.py: needs MROS2_ROOT (mros2 v0.5.4): docs/testing.md',
              file=sys.stderr)
        return 2
    work = options.keep or tempfile.mkdtemp(prefix='fragment_receive_')
    os.makedirs(work, exist_ok=True)
    patched = checkout(work, True)
    timer = build(work, patched, 'timer', (SAMPLE, 1))
    datagrams = {what: sample_datagrams(fragment) for what, fragment in CASES}
    script = ''.join('case %s\n' % what +
                     ''.join(datagram.hex() + '\n' for datagram in datagrams[what])
                     for what, _ in CASES)
    lines = subprocess.run(timer, input=script, capture_output=True, text=True,
                           check=True).stdout.splitlines()
    print('| sample of %d bytes given as | datagrams | receive time, median (µs) | ratio | '
          'delivered |' % SAMPLE)
    print('|---|---:|---:|---:|---:|')
    base = None
    for (what, _), line in zip(CASES, lines):
        nanoseconds, delivered = (int(field) for field in line.rsplit(' ', 2)[1:])
        base = base or nanoseconds
        print('| %s | %d | %.2f | %.1f | %d |' % (
            what, len(datagrams[what]), nanoseconds / 1000, nanoseconds / base, delivered))
    print()
    print('| settings | sizeof(MessageReceiver), x86-64 | 32-bit ARM | the patch adds (ARM) |')
    print('|---|---:|---:|---:|')
    base = None
    for index, (what, settings) in enumerate(RAM_SETTINGS):
        root = patched if settings is not None else checkout(work, False)
        sizes = []
        for arm in (False, True):
            program = build(work, root, 'size_%d_%s' % (index, arm), settings, arm)
            sizes.append(int(subprocess.run(program + ['sizeof'], capture_output=True,
                                            text=True, check=True).stdout))
        base = base or sizes[1]
        print('| %s | %d | %d | %d |' % (what, sizes[0], sizes[1], sizes[1] - base))
    if not options.keep:
        shutil.rmtree(work)
    return 0


if __name__ == '__main__':
    sys.exit(main())
