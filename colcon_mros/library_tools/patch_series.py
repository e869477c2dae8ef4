"""A patch series for a user's library: fixes kept as small unified diffs
against the library's public sources (``*.patch`` in one directory, applied
in the order of its ``series`` file, as quilt keeps them), never as a copy
of the library. Each mROS line's series is a :class:`PatchSeries` (mROS
v1's: :mod:`colcon_mros.library_tools.mros_v1.patches`).

A series is applied to a checkout (only files below its library
directory), checked, or taken out. A hunk applies where its line numbers
say, or, as GNU patch does without fuzz, at the nearest place where every
line it expects is there (an earlier patch of the series may have moved
it); where the checkout differs, nothing is written and the error names the
file, the line and the patch. A patch already applied is left as it is.
"""

import dataclasses
import os
import re

from colcon_mros.core.output import write_files
from colcon_mros.errors import GenmrosError

# The patches' order, one file name a line ('#' starts a comment).
SERIES = 'series'
_HUNK = re.compile(r'^@@ -(\d+)(?:,(\d+))? \+(\d+)(?:,(\d+))? @@')


@dataclasses.dataclass(frozen=True)
class PatchSeries:
    """A series: the directory of its patches and series file, and the one
    directory of the checkout its patches may change."""

    directory: str
    library_dir: str


@dataclasses.dataclass
class Hunk:
    """Lines of one place in a file: before (old) and after (new) the fix,
    context included, and the lines each starts at."""

    old_start: int
    new_start: int
    old: list
    new: list


@dataclasses.dataclass
class Patch:
    """One fix: its name, what it fixes (the text before the diff), and its
    hunks by file (relative to the checkout)."""

    name: str
    description: str
    files: dict

    def reversed(self):
        return Patch(self.name, self.description,
                     {path: [Hunk(hunk.new_start, hunk.old_start, hunk.new, hunk.old)
                             for hunk in hunks]
                      for path, hunks in self.files.items()})


def _check_counts(hunk, counts, path, line):
    """A hunk must have the lines its header counts."""
    if hunk is not None and (len(hunk.old), len(hunk.new)) != counts:
        raise GenmrosError('the hunk counts %d old and %d new lines but has %d and %d'
                           % (counts + (len(hunk.old), len(hunk.new))), path, line)


def read_patch(path, library_dir):
    """The Patch of a unified diff (``diff -u`` or ``git diff``) at path,
    which may change files below library_dir only."""
    name = os.path.splitext(os.path.basename(path))[0]
    files = {}
    hunk = counts = header_line = None
    target = None
    with open(path, encoding='utf-8') as stream:
        lines = stream.read().splitlines()
    first_diff = next((index for index, line in enumerate(lines) if line.startswith('--- ')),
                      len(lines))
    description = ' '.join(' '.join(lines[:first_diff]).split())
    for number, line in enumerate(lines, 1):
        header = _HUNK.match(line)
        in_hunk = hunk is not None and (len(hunk.old), len(hunk.new)) != counts
        if in_hunk and line[:1] in (' ', '-', '+', ''):
            if line[:1] != '+':
                hunk.old.append(line[1:])
            if line[:1] != '-':
                hunk.new.append(line[1:])
            continue
        if line.startswith('\\'):  # "\ No newline at end of file"
            continue
        _check_counts(hunk, counts, path, header_line)
        hunk = None
        if line.startswith('+++ '):
            target = re.sub(r'^b/', '', line[4:].split('\t')[0].strip())
            if not target.startswith(library_dir + '/'):
                raise GenmrosError('patches may change %s/ only, not %s' % (library_dir, target),
                                   path, number)
            files[target] = []
        elif header:
            if target is None:
                raise GenmrosError('a hunk before its file\'s +++ line', path, number)
            hunk = Hunk(int(header.group(1)), int(header.group(3)), [], [])
            counts = tuple(1 if count is None else int(count)
                           for count in (header.group(2), header.group(4)))
            header_line = number
            files[target].append(hunk)
    _check_counts(hunk, counts, path, header_line)
    if not files:
        raise GenmrosError('no file changes in this patch', path)
    return Patch(name, description, files)


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
    return [read_patch(os.path.join(directory, name), patch_series.library_dir) for name in names]


class _Mismatch(Exception):
    def __init__(self, path, line):
        super().__init__(path, line)
        self.path = path
        self.line = line


def _nearest_match(lines, hunk, expected):
    """The start of the place nearest to expected (0-based) where lines hold
    every line of the hunk, as GNU patch looks for it; or None."""
    wanted = hunk.old
    for distance in range(len(lines) + 1):
        for start in (expected - distance, expected + distance):
            if 0 <= start <= len(lines) - len(wanted) and [
                    line.rstrip('\r\n') for line in lines[start:start + len(wanted)]] == wanted:
                return start
    return None


def patched_text(text, hunks, path):
    """text with hunks applied, in order, each at its line (moved by the
    lines the hunks before it added or took away) or at the nearest place
    its lines are; _Mismatch at the first differing line of the file where
    a hunk's lines are nowhere."""
    lines = text.splitlines(keepends=True)
    # Lines the hunks applied so far added (or took away), and how far the
    # last hunk was from its line: GNU patch looks for the next one there.
    grown = offset = 0
    for hunk in hunks:
        at_its_line = max(hunk.old_start - 1, 0) + grown
        expected = at_its_line + offset
        start = _nearest_match(lines, hunk, expected)
        if start is None:
            found = [line.rstrip('\r\n') for line in lines[expected:expected + len(hunk.old)]]
            mismatch = next((index for index, (have, want) in enumerate(zip(found, hunk.old))
                             if have != want), len(found))
            raise _Mismatch(path, expected - grown + mismatch + 1)
        offset = start - at_its_line
        ending = '\r\n' if lines and lines[min(start, len(lines) - 1)].endswith('\r\n') else '\n'
        lines[start:start + len(hunk.old)] = [line + ending for line in hunk.new]
        grown += len(hunk.new) - len(hunk.old)
    return ''.join(lines)


def _read(root, path):
    full = os.path.join(root, path)
    try:
        with open(full, encoding='utf-8', newline='') as stream:
            return stream.read()
    except OSError as error:
        raise GenmrosError('cannot read: %s' % error.strerror, full)
    except UnicodeDecodeError:
        raise GenmrosError('not UTF-8 text, which the patches expect', full)


def _changed_texts(root, patch, texts):
    """{path: text} after patch, from texts (read from root where absent)."""
    changed = {}
    for path, hunks in patch.files.items():
        text = texts[path] if path in texts else _read(root, path)
        changed[path] = patched_text(text, hunks, path)
    return changed


def patch_states(root, patches):
    """[(patch, applied)] for the checkout at root: True where the patch's
    changes are there, False where the lines it changes are as it expects;
    a GenmrosError naming the file, line and patch where neither is so."""
    states = []
    for patch in patches:
        try:
            _changed_texts(root, patch, {})
            states.append((patch, False))
            continue
        except _Mismatch as unapplied:
            try:
                _changed_texts(root, patch.reversed(), {})
            except _Mismatch:
                raise GenmrosError(
                    'differs from what patch %s expects (another version of the library, or '
                    'changed by hand): nothing is changed' % patch.name,
                    os.path.join(root, unapplied.path), unapplied.line)
        states.append((patch, True))
    return states


def apply_patches(root, patches, revert=False):
    """Applies patches to the checkout at root (revert: takes them out);
    returns the names of the patches it applied (or took out). Every file
    is checked before any is written; each is written whole, atomically."""
    texts = {}
    done = []
    states = patch_states(root, patches)
    # Taken out in the reverse order: each from the text it was applied to.
    for patch, applied in reversed(states) if revert else states:
        if applied != revert:
            continue
        texts.update(_changed_texts(root, patch.reversed() if revert else patch, texts))
        done.append(patch.name)
    write_files(root, texts)
    return done

