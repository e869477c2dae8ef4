#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""How genmros' generator scales with deep, wide and long definitions.

    /usr/bin/python3 bench/generator_scaling.py [--baseline CHECKOUT]

For each case it times a whole ``genmros mros-v1-export`` of a generated package,
and, side by side in the same run, genmsg's own compute_md5 and
compute_full_text over the same types (what genmros used before it computed
each type's identity once), or, with --baseline, the genmros of another
checkout. A case that takes longer than --limit seconds is stopped and shown
as '>limit'.
"""

import argparse
import os
import subprocess
import sys
import tempfile
import time

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, REPO)  # the shared testing package

from testing.ros_paths import prefix_arguments, ros1_prefixes  # noqa: E402

PACKAGE_XML = (
    '<?xml version="1.0"?>\n'
    '<package format="2"><name>%s</name><version>0.0.1</version>'
    '<description>bench</description>\n'
    '<maintainer email="dev@colcon-mros.invalid">colcon-mros developers</maintainer>'
    '<license>BSD</license>\n'
    '<buildtool_depend>catkin</buildtool_depend></package>\n')


def chain(depth):
    return {'D%d.msg' % i: 'int32 level\n' + ('D%d next\n' % (i + 1) if i + 1 < depth else '')
            for i in range(depth)}


def diamond(depth):
    return {'W%d.msg' % i: ('W%d left\nW%d right\n' % (i + 1, i + 1) if i + 1 < depth else '')
            for i in range(depth)}


def long_file(lines):
    return {'Long.msg': ''.join('int32 field%d\n' % i for i in range(lines - 1)) + 'int32 1bad\n'}


CASES = [
    ('chain, 250 levels', True, lambda: chain(250)),
    ('diamond, 16 levels', True, lambda: diamond(16)),
    ('diamond, 20 levels', True, lambda: diamond(20)),
    ('diamond, 22 levels', True, lambda: diamond(22)),
    ('diamond, 40 levels', True, lambda: diamond(40)),
    ('20,000 lines, error on the last', False, lambda: long_file(20000)),
]

# Every type's MD5 sum and full text, as an export needs them for its headers.
GENMSG_IDENTITY = '''
import os, sys
from genmsg import gentools, msg_loader
search_path = {"bench": [sys.argv[1]]}
context = msg_loader.MsgContext.create_default()
for name in sorted(os.listdir(sys.argv[1])):
    spec = msg_loader.load_msg_by_type(context, "bench/" + name[:-4], search_path)
    msg_loader.load_depends(context, spec, search_path)
    gentools.compute_md5(context, spec)
    gentools.compute_full_text(context, spec)
'''


def _timed(command, limit, cwd=None):
    """(seconds or None past the limit, how it ended: '', 'error line' or 'traceback')."""
    started = time.monotonic()
    try:
        result = subprocess.run(command, cwd=cwd, capture_output=True, text=True, timeout=limit)
    except subprocess.TimeoutExpired:
        return None, ''
    ending = ''
    if 'Traceback' in result.stderr:
        ending = 'traceback'
    elif result.returncode != 0:
        ending = 'error line'
    return time.monotonic() - started, ending


def _format(timing, limit):
    seconds, ending = timing
    text = '>%ds' % limit if seconds is None else '%.2fs' % seconds
    return '%s (%s)' % (text, ending) if ending else text


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('--baseline', metavar='CHECKOUT',
                        help='compare with the genmros of this checkout')
    parser.add_argument('--limit', type=int, default=60,
                        help='seconds before a case is stopped (default: 60)')
    options = parser.parse_args(argv)
    other = ('genmros at %s' % options.baseline if options.baseline
             else "genmsg's compute_md5 + full text")
    print('| case | genmros mros-v1-export | %s | ratio |' % other)
    print('|---|---|---|---|')
    for label, identity, files in CASES:
        with tempfile.TemporaryDirectory() as root:
            package = os.path.join(root, 'ws', 'src', 'bench')
            os.makedirs(os.path.join(package, 'msg'))
            with open(os.path.join(package, 'package.xml'), 'w') as stream:
                stream.write(PACKAGE_XML % 'bench')
            for name, text in files().items():
                with open(os.path.join(package, 'msg', name), 'w') as stream:
                    stream.write(text)
            export = ['mros-v1-export', '--workspace', os.path.join(root, 'ws'),
                      *prefix_arguments(ros1_prefixes())]
            ours = _timed([sys.executable, '-m', 'colcon_mros'] + export
                          + ['-o', os.path.join(root, 'out')], options.limit, cwd=REPO)
            if options.baseline:
                theirs = _timed([sys.executable, '-m', 'colcon_mros'] + export
                                + ['-o', os.path.join(root, 'baseline')], options.limit,
                                cwd=options.baseline)
            elif identity:
                theirs = _timed([sys.executable, '-c', GENMSG_IDENTITY,
                                 os.path.join(package, 'msg')], options.limit)
            else:
                theirs = None
            if theirs is None:
                print('| %s | %s | n/a | - |' % (label, _format(ours, options.limit)))
                continue
            comparable = None not in (
                ours[0], theirs[0]) and 'traceback' not in (ours[1], theirs[1])
            ratio = '%.2f' % (ours[0] / theirs[0]) if comparable else '-'
            print('| %s | %s | %s | %s |' % (label, _format(ours, options.limit),
                                             _format(theirs, options.limit), ratio))
    return 0


if __name__ == '__main__':
    sys.exit(main())
