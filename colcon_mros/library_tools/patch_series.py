# SPDX-License-Identifier: BSD-3-Clause
"""A patch series for a user's library, applied by GNU patch: fixes kept as
small unified diffs against the library's public sources (``*.patch`` in one
directory, applied in the order of its ``series`` file, as quilt keeps
them), never as a copy of the library. Each mROS line's series is a
:class:`PatchSeries` (mROS v1's: :mod:`colcon_mros.library_tools.mros_v1.patches`).

GNU patch applies each patch without fuzz (``patch -p1 -F0
--no-backup-if-mismatch -r -``), in series order, to a copy of the files
the series touches, because several patches change the same file. The
user's checkout is written, file by file and each one atomically, only once
the whole series has gone through on the copy; a refusal names the patch,
the file and the hunk that does not apply, and leaves the checkout as it
was. A patch whose reverse applies (a reverse dry run) is already in and is
not applied twice: which are in is found from the last patch back, each one
found in taken out of the copy before the one before it is tried. Taking a
series out goes the same way, in reverse order.
"""

import dataclasses
import os
import re
import shutil
import subprocess
import tempfile

from colcon_mros.core.output import write_files
from colcon_mros.errors import GenmrosError

# The patches' order, one file name a line ('#' starts a comment).
SERIES = 'series'
# GNU patch as the series wants it: paths below the checkout (-p1), no fuzz,
# no .orig or .rej files, no question asked (and no reversed patch assumed).
PATCH = ('patch', '-p1', '-F0', '--no-backup-if-mismatch', '-r', '-', '--force')
# Its messages in one language, file names as they are.
_PATCH_ENVIRONMENT = {'LC_ALL': 'C', 'QUOTING_STYLE': 'literal'}
_FILE_LINE = re.compile(r'^(?:---|\+\+\+) (\S+)')
_CHECKING = re.compile(r'^(?:checking|patching) file (.+)$')
_FAILED_HUNK = re.compile(r'^Hunk #(\d+) FAILED')
_HUNK_HEADER = re.compile(r'^@@ -(\d+)')


@dataclasses.dataclass(frozen=True)
class PatchSeries:
    """A series: the directory of its patches and series file, and the
    directories of the checkout its patches may change."""

    directory: str
    library_dirs: tuple


@dataclasses.dataclass
class Patch:
    """One fix: its name, its file, what it fixes (the text before the
    diff), and the files it changes, added and removed ones included
    (relative to the checkout)."""

    name: str
    path: str
    description: str
    files: list


def read_patch(path, library_dirs):
    """The Patch of a unified diff (``diff -u`` or ``git diff``) at path,
    which may change files below library_dirs only."""
    try:
        with open(path, encoding='utf-8') as stream:
            lines = stream.read().splitlines()
    except (OSError, UnicodeDecodeError) as error:
        raise GenmrosError('cannot read: %s' % (getattr(error, 'strerror', None) or error), path)
    first_diff = next((index for index, line in enumerate(lines)
                       if line.startswith(('--- ', 'diff '))), len(lines))
    description = ' '.join(' '.join(lines[:first_diff]).split())
    files = []
    old = None
    for number, line in enumerate(lines, 1):
        match = _FILE_LINE.match(line)
        if not match:
            continue
        if line.startswith('--- '):
            old = (match.group(1), number)
            continue
        # A file's +++ line names it; a removed file's (+++ /dev/null), its --- line.
        name, number = old if match.group(1) == '/dev/null' else (match.group(1), number)
        target = name.split('/', 1)[-1]  # -p1: without a/ or b/
        if not target.startswith(tuple(directory + '/' for directory in library_dirs)):
            raise GenmrosError('patches may change %s only, not %s' % (
                ', '.join(directory + '/' for directory in library_dirs), target), path, number)
        if target not in files:
            files.append(target)
    if not files:
        raise GenmrosError('no file changes in this patch', path)
    return Patch(os.path.splitext(os.path.basename(path))[0], path, description, files)


def read_series(patch_series):
    """Every patch of a PatchSeries, in the order of its series file."""
    directory = patch_series.directory
    series = os.path.join(directory, SERIES)
    try:
        with open(series, encoding='utf-8') as stream:
            entries = [(number, line.split('#')[0].strip())
                       for number, line in enumerate(stream, 1)]
    except OSError as error:
        raise GenmrosError('cannot read the series file: %s' % error.strerror, series)
    names = []
    for number, name in entries:
        if not name:
            continue
        if not os.path.isfile(os.path.join(directory, name)) or name in names:
            raise GenmrosError('%s: %s' % (name, 'listed twice' if name in names
                                           else 'no such patch'), series, number)
        names.append(name)
    unlisted = sorted(set(name for name in os.listdir(directory) if name.endswith('.patch'))
                      - set(names))
    if unlisted:
        raise GenmrosError('patches not in the series: %s' % ', '.join(unlisted), series)
    return [read_patch(os.path.join(directory, name), patch_series.library_dirs)
            for name in names]


def _run_patch(directory, patch, reverse=False, dry_run=False):
    """GNU patch over the copy in directory; the CompletedProcess."""
    argv = list(PATCH) + ['-d', directory, '-i', os.path.abspath(patch.path)]
    argv += ['-R'] if reverse else []
    argv += ['--dry-run'] if dry_run else []
    try:
        return subprocess.run(argv, capture_output=True, text=True,
                              env=dict(os.environ, **_PATCH_ENVIRONMENT))
    except OSError as error:
        raise GenmrosError('cannot run GNU patch (Debian: apt-get install patch): %s'
                           % error.strerror)


def _hunk_start(patch, path, number):
    """The line hunk #number of patch's changes to path starts at, in the
    file as the patch expects it (its @@ -LINE header)."""
    current, count = None, 0
    with open(patch.path, encoding='utf-8') as stream:
        for line in stream:
            match = _FILE_LINE.match(line)
            if line.startswith('+++ ') and match:
                current, count = match.group(1).split('/', 1)[-1], 0
            elif current == path and _HUNK_HEADER.match(line):
                count += 1
                if count == number:
                    return int(_HUNK_HEADER.match(line).group(1))
    return None


def _refusal(root, patch, result):
    """The one-line error for a patch GNU patch would not apply: the file,
    the hunk and the line it starts at."""
    current = None
    for line in result.stdout.splitlines():
        checking = _CHECKING.match(line)
        if checking:
            current = checking.group(1)
        failed = _FAILED_HUNK.match(line)
        if failed and current:
            number = int(failed.group(1))
            return GenmrosError(
                'differs from what hunk #%d of patch %s expects from here on (another version of '
                'the library, or changed by hand): nothing is changed' % (number, patch.name),
                os.path.join(root, current), _hunk_start(patch, current, number))
        if line.startswith("can't find file to patch") or 'No such file' in line:
            missing = next((path for path in patch.files
                            if not os.path.exists(os.path.join(root, path))), None)
            if missing:
                return GenmrosError('patch %s changes this file, which is not there: nothing is '
                                    'changed' % patch.name, os.path.join(root, missing))
    detail = (result.stdout + result.stderr).strip().splitlines()
    return GenmrosError('GNU patch refuses patch %s (%s): nothing is changed'
                        % (patch.name, detail[-1] if detail else 'exit %d' % result.returncode),
                        patch.path)


class _Copy:
    """The files a series touches, copied from the checkout at root into a
    temporary directory, where GNU patch changes them."""

    def __init__(self, root, patches):
        self.root = root
        self.files = sorted({path for patch in patches for path in patch.files})
        self._temporary = tempfile.TemporaryDirectory(prefix='genmros-patches-')
        self.directory = self._temporary.name
        for path in self.files:
            source = os.path.join(root, path)
            if os.path.isfile(source):
                os.makedirs(os.path.dirname(os.path.join(self.directory, path)), exist_ok=True)
                shutil.copy2(source, os.path.join(self.directory, path))

    def apply(self, patch, reverse=False, dry_run=False):
        """Apply patch (reverse: take it out) on the copy; None if it went
        in whole, else the refusal GenmrosError. A refused patch may leave
        some of its hunks on the copy: the refusal ends the run, and the
        copy goes with it."""
        result = _run_patch(self.directory, patch, reverse, dry_run)
        return None if result.returncode == 0 else _refusal(self.root, patch, result)

    def is_in(self, patch):
        """Whether patch is already in the copy: its reverse applies."""
        return _run_patch(self.directory, patch, reverse=True, dry_run=True).returncode == 0

    def write_back(self):
        """Write every file the copy changed into the checkout (each file
        whole, atomically), and remove those the series removed."""
        changed, removed = {}, []
        for path in self.files:
            copy, original = os.path.join(self.directory, path), os.path.join(self.root, path)
            if os.path.isfile(copy):
                with open(copy, 'rb') as stream:
                    changed[path] = stream.read()
            elif os.path.isfile(original):
                removed.append(original)
        write_files(self.root, changed)
        for path in removed:
            os.unlink(path)

    def close(self):
        self._temporary.cleanup()

    def __enter__(self):
        return self

    def __exit__(self, *exception):
        self.close()


def _go_through(copy, patches, revert):
    """[(patch, was it in)] for patches in series order, leaving the copy with
    every patch in (with revert, every patch out); a GenmrosError for the first
    that does not apply.

    Which are in is found from the last back: one whose reverse applies is in,
    and is taken out of the copy, so that each patch before it is tried on the
    library as that patch left it (a later patch may change lines an earlier
    one's hunks hold as context). Then every patch goes in, in series order,
    which checks that those not in apply, and with revert all go out again."""
    states = []
    for patch in reversed(patches):
        is_in = copy.is_in(patch)
        if is_in:
            copy.apply(patch, reverse=True)
        states.append((patch, is_in))
    for patch in patches:
        refusal = copy.apply(patch)
        if refusal is not None:
            raise refusal
    if revert:
        for patch in reversed(patches):
            copy.apply(patch, reverse=True)
    return list(reversed(states))


def patch_states(root, patches):
    """[(patch, applied)] for the checkout at root, in series order; a
    GenmrosError naming the file, the hunk and the patch where a patch is
    neither in nor applies."""
    with _Copy(root, patches) as copy:
        return _go_through(copy, patches, revert=False)


def apply_patches(root, patches, revert=False):
    """Applies patches to the checkout at root (revert: takes them out),
    once all of them went through on a copy; returns the names of the
    patches it applied (or took out), in the order it did."""
    with _Copy(root, patches) as copy:
        states = _go_through(copy, patches, revert)
        copy.write_back()
    done = [patch.name for patch, was_in in states if was_in == revert]
    return list(reversed(done)) if revert else done
