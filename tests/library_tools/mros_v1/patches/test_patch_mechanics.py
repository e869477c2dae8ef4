"""The patch set's mechanics (colcon_mros.library_tools.patch_series) on a small
tree of the tests' own (tests/fixtures/patch_tree): library/, copied to a
checkout's mros-lib/ for each test, two patches of its own, and patched/,
the same files with the fixes written by hand. Apply, check, revert, refusal of a tree changed by hand, and whole-file
writes; the real patch set on a real checkout is test_patch_set.py's."""

import filecmp
import os
import shutil

import pytest

from colcon_mros.errors import GenmrosError
from colcon_mros.library_tools.patch_series import (PatchSeries, apply_patches, patch_states,
                                                    read_series)

from conftest import REPO

TREE = os.path.join(REPO, 'tests', 'fixtures', 'patch_tree')


def patch_set(directory):
    return read_series(PatchSeries(directory, 'mros-lib'))


PATCHES = patch_set(os.path.join(TREE, 'patches'))
FILES = ('mros-lib/api/ros.cpp', 'mros-lib/comm/socket.c')


@pytest.fixture
def library(tmp_path):
    """A checkout whose mros-lib/ holds the fixture's library files."""
    shutil.copytree(os.path.join(TREE, 'library'), str(tmp_path / 'checkout' / 'mros-lib'))
    return str(tmp_path / 'checkout')


def _fixture_file(tree, path):
    """path (below a checkout) in the fixture's tree ('library' or 'patched')."""
    return os.path.join(TREE, tree, os.path.relpath(path, 'mros-lib'))


def _equal_to(root, tree):
    return all(filecmp.cmp(os.path.join(root, path), _fixture_file(tree, path), shallow=False)
               for path in FILES)


def _listing(root):
    return sorted(os.path.relpath(os.path.join(directory, name), root)
                  for directory, _, names in os.walk(root) for name in names)


def test_the_patches_are_read_in_the_series_order_with_their_descriptions():
    assert [(patch.name, sorted(patch.files)) for patch in PATCHES] == [
        ('publish-without-memory', ['mros-lib/api/ros.cpp']),
        ('bound-received-lengths', ['mros-lib/comm/socket.c'])]
    assert PATCHES[1].description == ('Bounds the lengths the library receives: a length word '
                                      'beyond the buffer is refused.')
    assert [len(hunks) for patch in PATCHES for hunks in patch.files.values()] == [1, 2]


def _patch_dir(tmp_path, series, **texts):
    """A copy of the fixture's patches with another series and texts."""
    directory = tmp_path / 'patches'
    shutil.copytree(os.path.join(TREE, 'patches'), str(directory))
    (directory / 'series').write_text(series)
    for name, text in texts.items():
        (directory / name).write_text(text)
    return str(directory)


def test_a_patch_outside_the_series_or_a_name_it_lacks_is_refused(tmp_path):
    directory = _patch_dir(tmp_path, 'bound-received-lengths.patch\n')
    with pytest.raises(GenmrosError) as refused:
        patch_set(directory)
    assert str(refused.value) == '%s: patches not in the series: publish-without-memory.patch' \
        % os.path.join(directory, 'series')
    directory = _patch_dir(tmp_path / 'again', '# comment\nbound-received-lengths.patch\n'
                           'publish-without-memory.patch\nmissing.patch\n')
    with pytest.raises(GenmrosError) as refused:
        patch_set(directory)
    assert str(refused.value) == '%s:4: missing.patch: no such patch' % os.path.join(
        directory, 'series')


def test_a_hunk_must_have_the_lines_its_header_counts(tmp_path):
    with open(os.path.join(TREE, 'patches', 'publish-without-memory.patch')) as stream:
        text = stream.read()
    # One added line taken out: the header still counts it.
    short = text.replace('+    return;\n', '', 1)
    directory = _patch_dir(tmp_path, 'publish-without-memory.patch\n'
                           'bound-received-lengths.patch\n',
                           **{'publish-without-memory.patch': short})
    header = short.splitlines().index('@@ -4,6 +4,9 @@') + 1
    with pytest.raises(GenmrosError) as refused:
        patch_set(directory)
    assert str(refused.value) == ('%s:%d: the hunk counts 6 old and 9 new lines but has 6 and 8'
                                  % (os.path.join(directory, 'publish-without-memory.patch'),
                                     header))


def test_apply_check_and_revert(library):
    assert [applied for _, applied in patch_states(library, PATCHES)] == [False, False]
    inodes = {path: os.stat(os.path.join(library, path)).st_ino for path in FILES}
    assert apply_patches(library, PATCHES) == [
        'publish-without-memory', 'bound-received-lengths']
    assert _equal_to(library, 'patched')
    # Each file replaced whole, and no temporary left beside it.
    assert all(os.stat(os.path.join(library, path)).st_ino != inodes[path] for path in FILES)
    assert _listing(library) == sorted(FILES)
    assert [applied for _, applied in patch_states(library, PATCHES)] == [True, True]

    times = {path: os.stat(os.path.join(library, path)).st_mtime_ns for path in FILES}
    assert apply_patches(library, PATCHES) == []
    assert times == {path: os.stat(os.path.join(library, path)).st_mtime_ns for path in FILES}

    assert apply_patches(library, PATCHES, revert=True) == [
        'bound-received-lengths', 'publish-without-memory']
    assert _equal_to(library, 'library')


def test_one_patch_applied_the_other_not(library):
    assert apply_patches(library, PATCHES[1:]) == ['bound-received-lengths']
    assert [applied for _, applied in patch_states(library, PATCHES)] == [False, True]
    assert apply_patches(library, PATCHES) == ['publish-without-memory']
    assert _equal_to(library, 'patched')


def test_a_hunk_goes_to_the_nearest_place_its_lines_are(library):
    # Two lines added at the top move every hunk of socket.c down by two.
    socket_c = os.path.join(library, 'mros-lib', 'comm', 'socket.c')
    with open(socket_c) as stream:
        text = stream.read()
    with open(socket_c, 'w') as stream:
        stream.write('/* A note. */\n\n' + text)
    assert apply_patches(library, PATCHES) == [
        'publish-without-memory', 'bound-received-lengths']
    with open(_fixture_file('patched', 'mros-lib/comm/socket.c')) as stream:
        patched = stream.read()
    with open(socket_c) as stream:
        assert stream.read() == '/* A note. */\n\n' + patched


def test_a_line_changed_by_hand_is_refused_and_nothing_is_written(library):
    socket_c = os.path.join(library, 'mros-lib', 'comm', 'socket.c')
    with open(socket_c) as stream:
        lines = stream.readlines()
    changed = lines.index('int receive_body(int socket, char *buffer) {\n')
    lines[changed] = 'int receive_body(int socket, char *buffer, size_t size) {\n'
    with open(socket_c, 'w') as stream:
        stream.writelines(lines)
    before = {path: open(os.path.join(library, path)).read() for path in FILES}
    with pytest.raises(GenmrosError) as refused:
        apply_patches(library, PATCHES)
    assert str(refused.value) == (
        '%s:%d: differs from what patch bound-received-lengths expects (another version of the '
        'library, or changed by hand): nothing is changed' % (socket_c, changed + 1))
    # ros.cpp, which the other patch would change, is as it was too.
    assert before == {path: open(os.path.join(library, path)).read() for path in FILES}
    assert _listing(library) == sorted(FILES)


def test_a_missing_file_is_named(library):
    os.unlink(os.path.join(library, 'mros-lib', 'api', 'ros.cpp'))
    with pytest.raises(GenmrosError) as refused:
        apply_patches(library, PATCHES)
    assert str(refused.value) == '%s: cannot read: No such file or directory' % os.path.join(
        library, 'mros-lib/api/ros.cpp')
    assert filecmp.cmp(os.path.join(library, 'mros-lib/comm/socket.c'),
                       _fixture_file('library', 'mros-lib/comm/socket.c'), shallow=False)
