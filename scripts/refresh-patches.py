#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Rewrites genmros' patch series for the mROS v1 library (colcon_mros/
library_tools/mros_v1/patches, in the order of its series file) as `diff -u`
writes them: each patch applied alone by GNU patch to the checkout's
library as it is, then diffed against it (3 lines of context, a/ and b/
paths), so that each stays a diff against the library as it is and applies
alone too. Its description (the text before the diff) is kept. At the end
the whole series must go in, in order, on a copy. For a maintainer, after a
patch was changed by hand; it reads the checkout and writes only the patch
files. The checkout should be the commit the series file names.

  /usr/bin/python3 scripts/refresh-patches.py MROS_CHECKOUT
"""

import os
import shutil
import subprocess
import sys
import tempfile

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, REPO)  # this checkout's patch series

from colcon_mros.library_tools.mros_v1.patches import MROS_V1_SERIES, mros_v1_patches  # noqa: E402
from colcon_mros.library_tools.patch_series import PATCH, apply_patches  # noqa: E402


def _diff(before, after, path):
    """`diff -u` of one file, a/path to b/path (/dev/null for a side without it)."""
    old = os.path.join(before, path)
    new = os.path.join(after, path)
    labels = ['--label', 'a/' + path if os.path.exists(old) else '/dev/null',
              '--label', 'b/' + path if os.path.exists(new) else '/dev/null']
    files = [path if os.path.exists(path) else '/dev/null' for path in (old, new)]
    result = subprocess.run(['diff', '-u'] + labels + files, capture_output=True, text=True)
    if result.returncode > 1:
        raise SystemExit('diff failed: %s' % result.stderr.strip())
    return result.stdout


def refresh(root, patch, scratch):
    """The text of patch, diffed again against the library at root."""
    before, after = os.path.join(scratch, 'before'), os.path.join(scratch, 'after')
    for copy in (before, after):
        for path in patch.files:
            if os.path.isfile(os.path.join(root, path)):
                os.makedirs(os.path.dirname(os.path.join(copy, path)), exist_ok=True)
                shutil.copy2(os.path.join(root, path), os.path.join(copy, path))
    applied = subprocess.run(list(PATCH) + ['-d', after, '-i', patch.path], capture_output=True,
                             text=True)
    if applied.returncode != 0:
        raise SystemExit('%s does not apply alone to %s:\n%s' % (patch.path, root, applied.stdout))
    with open(patch.path, encoding='utf-8') as stream:
        text = stream.read()
    description = text[:text.index('--- ')] if '\n--- ' in '\n' + text else ''
    return description + ''.join(_diff(before, after, path) for path in patch.files)


def main():
    if len(sys.argv) != 2 or not os.path.isdir(os.path.join(sys.argv[1], 'mros-lib')):
        print(__doc__.strip().splitlines()[-1], file=sys.stderr)
        return 2
    root = sys.argv[1]
    for patch in mros_v1_patches():
        with tempfile.TemporaryDirectory(prefix='refresh-patches-') as scratch:
            text = refresh(root, patch, scratch)
        with open(patch.path, 'w', encoding='utf-8') as stream:
            stream.write(text)
    with tempfile.TemporaryDirectory(prefix='refresh-patches-') as scratch:
        for directory in MROS_V1_SERIES.library_dirs:
            shutil.copytree(os.path.join(root, directory), os.path.join(scratch, directory))
        apply_patches(scratch, mros_v1_patches())
    print('refreshed the patches of %s' % MROS_V1_SERIES.directory)
    return 0


if __name__ == '__main__':
    sys.exit(main())
