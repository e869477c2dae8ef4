#!/usr/bin/env python3
"""Rewrites genmros' patch set for the mROS v1 library (colcon_mros/
library_tools/mros_v1/patches, in the order of its series file) with the least context that keeps
each hunk in one place: the conventional 3 lines, more only where 3 would
also fit elsewhere in the file, as the library is and after the patches
before it in the series. Each patch stays a diff against the library as it
is, so it applies alone too. For a maintainer, after a patch was changed;
it reads the checkout and writes only the patch files.

  /usr/bin/python3 scripts/refresh-patches.py MROS_CHECKOUT
"""

import difflib
import os
import sys

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, REPO)  # this checkout's patch set

from colcon_mros.library_tools.mros_v1.patches import MROS_V1_SERIES, mros_v1_patches  # noqa: E402
from colcon_mros.library_tools.patch_series import SERIES, patched_text, read_patch  # noqa: E402

PATCH_DIR = MROS_V1_SERIES.directory

CONVENTIONAL_CONTEXT = 3


def places(lines, wanted):
    return [start for start in range(len(lines) - len(wanted) + 1)
            if lines[start:start + len(wanted)] == wanted]


def least_context_diff(path, before, after, texts_to_search):
    """The unified diff of before -> after (path's text) with the least
    context, from the conventional 3 up, whose every hunk has one place in
    each of texts_to_search."""
    old, new = before.splitlines(), after.splitlines()
    for context in range(CONVENTIONAL_CONTEXT, max(len(old), 1) + 1):
        diff = list(difflib.unified_diff(old, new, 'a/' + path, 'b/' + path, n=context,
                                         lineterm=''))
        hunks = [[line[1:] for line in hunk.splitlines()[1:] if line[:1] in (' ', '-')]
                 for hunk in '\n'.join(diff[2:]).split('\n@@')]
        if all(len(places(text.splitlines(), hunk)) == 1
               for hunk in hunks for text in texts_to_search):
            return diff
    raise SystemExit('%s: no context makes every hunk unique' % path)


def main():
    if len(sys.argv) != 2 or not os.path.isdir(os.path.join(sys.argv[1], 'mros-lib')):
        print(__doc__.strip().splitlines()[-1], file=sys.stderr)
        return 2
    root = sys.argv[1]
    series = {}  # path: its text after the patches so far
    for patch in mros_v1_patches():
        patch_path = os.path.join(PATCH_DIR, patch.name + '.patch')
        with open(patch_path, encoding='utf-8') as stream:
            text = stream.read()
        description = text[:text.index('\n--- ') + 1] if not text.startswith('--- ') else ''
        diff_lines = []
        for path, hunks in patch.files.items():
            with open(os.path.join(root, path), encoding='utf-8', newline='') as stream:
                original = stream.read()
            changed = patched_text(original, hunks, path)
            current = series.get(path, original)
            diff_lines += least_context_diff(path, original, changed, [original, current])
            series[path] = patched_text(current, hunks, path)
        with open(patch_path, 'w', encoding='utf-8') as stream:
            stream.write(description + '\n'.join(diff_lines) + '\n')
        read_patch(patch_path, MROS_V1_SERIES.library_dir)  # still a patch genmros reads
    print('refreshed the patches of %s' % os.path.join(PATCH_DIR, SERIES))
    return 0


if __name__ == '__main__':
    sys.exit(main())
