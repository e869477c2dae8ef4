"""The opt-in patch set for a user's mROS v1 library: fixes kept as small
unified diffs against the library's public sources (``*.patch`` beside this
module, applied in name order), never as a copy of the library.

``genmros mros-v1-harden MROS_ROOT`` applies them to a checkout (only files
below ``mros-lib/``), ``--check`` says whether they are, ``--revert`` takes
them out; ``genmros mros-v1-pc --hardened`` applies them to a copy. A patch
applies only where every line it expects is there as it expects it; where
the checkout differs, nothing is written and the error names the file, the
line and the patch. A patch already applied is left as it is.
"""

import dataclasses
import os
import re

from colcon_mros.errors import GenmrosError
from colcon_mros.generator.output import write_files

PATCH_DIR = os.path.dirname(os.path.abspath(__file__))
# Every path a patch names lies below this directory of the checkout.
LIBRARY_DIR = 'mros-lib'
_HUNK = re.compile(r'^@@ -(\d+)(?:,(\d+))? \+(\d+)(?:,(\d+))? @@')


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


def read_patch(path):
    """The Patch of a unified diff (``diff -u`` or ``git diff``) at path."""
    name = os.path.splitext(os.path.basename(path))[0]
    files = {}
    hunk = None
    target = None
    with open(path, encoding='utf-8') as stream:
        lines = stream.read().splitlines()
    first_diff = next((index for index, line in enumerate(lines) if line.startswith('--- ')),
                      len(lines))
    description = ' '.join(' '.join(lines[:first_diff]).split())
    for number, line in enumerate(lines, 1):
        header = _HUNK.match(line)
        if line.startswith('+++ '):
            target = re.sub(r'^b/', '', line[4:].split('\t')[0].strip())
            if not target.startswith(LIBRARY_DIR + '/'):
                raise GenmrosError('patches may change %s/ only, not %s' % (LIBRARY_DIR, target),
                                   path, number)
            files[target] = []
        elif line.startswith('--- ') or line.startswith('diff ') or line.startswith('index '):
            hunk = None
        elif header:
            if target is None:
                raise GenmrosError('a hunk before its file\'s +++ line', path, number)
            hunk = Hunk(int(header.group(1)), int(header.group(3)), [], [])
            files[target].append(hunk)
        elif hunk is not None and line[:1] in (' ', '-', '+'):
            if line[0] != '+':
                hunk.old.append(line[1:])
            if line[0] != '-':
                hunk.new.append(line[1:])
        elif hunk is not None and line == '':
            hunk.old.append('')
            hunk.new.append('')
        elif not line.startswith('\\'):
            hunk = None
    if not files:
        raise GenmrosError('no file changes in this patch', path)
    return Patch(name, description, files)


def patch_set(directory=PATCH_DIR):
    """Every patch of the set, in the order they apply."""
    return [read_patch(os.path.join(directory, name))
            for name in sorted(os.listdir(directory)) if name.endswith('.patch')]


class _Mismatch(Exception):
    def __init__(self, path, line):
        super().__init__(path, line)
        self.path = path
        self.line = line


def _patched_text(text, hunks, path):
    """text with hunks applied, in order; _Mismatch where a hunk's old lines
    are neither where it expects them (after the earlier hunks' shift) nor
    in one other place (where another patch moved them)."""
    lines = text.splitlines(keepends=True)
    shift = 0
    # Lines the hunks applied so far added (or took away): a mismatch is
    # reported at its line in text, not in the half-patched lines.
    grown = 0

    def found_at(start, count):
        return [line.rstrip('\r\n') for line in lines[start:start + count]]
    for hunk in hunks:
        start = max(hunk.old_start - 1, 0) + shift
        if found_at(start, len(hunk.old)) != hunk.old:
            elsewhere = [index for index in range(len(lines))
                         if found_at(index, len(hunk.old)) == hunk.old]
            if len(elsewhere) != 1:
                found = found_at(start, len(hunk.old))
                mismatch = next((index for index, (have, want) in enumerate(zip(found, hunk.old))
                                 if have != want), len(found))
                raise _Mismatch(path, start - grown + mismatch + 1)
            shift += elsewhere[0] - start
            start = elsewhere[0]
        ending = '\r\n' if lines and lines[min(start, len(lines) - 1)].endswith('\r\n') else '\n'
        lines[start:start + len(hunk.old)] = [line + ending for line in hunk.new]
        shift += len(hunk.new) - len(hunk.old)
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
        changed[path] = _patched_text(text, hunks, path)
    return changed


def patch_states(root, patches=None):
    """[(patch, applied)] for the checkout at root: True where the patch's
    changes are there, False where the lines it changes are as it expects;
    a GenmrosError naming the file, line and patch where neither is so."""
    states = []
    for patch in patches if patches is not None else patch_set():
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


def apply_patches(root, revert=False, patches=None):
    """Applies the patch set to the checkout at root (revert: takes it out);
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


def check_root(root):
    """root, if it is an mROS v1 checkout (with mros-lib/); else a GenmrosError."""
    if not os.path.isdir(os.path.join(root, LIBRARY_DIR)):
        raise GenmrosError('no %s/ here: not an mROS v1 checkout' % LIBRARY_DIR, root)
    return root
