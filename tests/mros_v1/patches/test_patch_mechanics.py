"""The patch set's mechanics (colcon_mros.mros_v1.patches.patch_set) on a small
tree of the tests' own (tests/fixtures/patch_tree): its library/ with two
patches of its own, and patched/, the same tree with the fixes written by
hand. Apply, check, revert, refusal of a tree changed by hand, and whole-file
writes; the real patch set on a real checkout is test_patch_set.py's."""

import filecmp
import os
import shutil

import pytest

from colcon_mros.errors import GenmrosError
from colcon_mros.mros_v1.patches.patch_set import apply_patches, patch_set, patch_states

TREE = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))),
                    'fixtures', 'patch_tree')
PATCHES = patch_set(os.path.join(TREE, 'patches'))
FILES = ('mros-lib/api/ros.cpp', 'mros-lib/comm/socket.c')


@pytest.fixture
def library(tmp_path):
    shutil.copytree(os.path.join(TREE, 'library'), str(tmp_path / 'library'))
    return str(tmp_path / 'library')


def _equal_to(root, tree):
    return all(filecmp.cmp(os.path.join(root, path), os.path.join(TREE, tree, path), shallow=False)
               for path in FILES)


def _listing(root):
    return sorted(os.path.relpath(os.path.join(directory, name), root)
                  for directory, _, names in os.walk(root) for name in names)


def test_the_patches_are_read_in_name_order_with_their_descriptions():
    assert [(patch.name, sorted(patch.files)) for patch in PATCHES] == [
        ('bound-received-lengths', ['mros-lib/comm/socket.c']),
        ('publish-without-memory', ['mros-lib/api/ros.cpp'])]
    assert PATCHES[0].description == ('Bounds the lengths the library receives: a length word '
                                      'beyond the buffer is refused.')
    assert [len(hunks) for patch in PATCHES for hunks in patch.files.values()] == [2, 1]


def test_apply_check_and_revert(library):
    assert [applied for _, applied in patch_states(library, PATCHES)] == [False, False]
    inodes = {path: os.stat(os.path.join(library, path)).st_ino for path in FILES}
    assert apply_patches(library, patches=PATCHES) == [
        'bound-received-lengths', 'publish-without-memory']
    assert _equal_to(library, 'patched')
    # Each file replaced whole, and no temporary left beside it.
    assert all(os.stat(os.path.join(library, path)).st_ino != inodes[path] for path in FILES)
    assert _listing(library) == sorted(FILES)
    assert [applied for _, applied in patch_states(library, PATCHES)] == [True, True]

    times = {path: os.stat(os.path.join(library, path)).st_mtime_ns for path in FILES}
    assert apply_patches(library, patches=PATCHES) == []
    assert times == {path: os.stat(os.path.join(library, path)).st_mtime_ns for path in FILES}

    assert apply_patches(library, revert=True, patches=PATCHES) == [
        'publish-without-memory', 'bound-received-lengths']
    assert _equal_to(library, 'library')


def test_one_patch_applied_the_other_not(library):
    assert apply_patches(library, patches=PATCHES[1:]) == ['publish-without-memory']
    assert [applied for _, applied in patch_states(library, PATCHES)] == [False, True]
    assert apply_patches(library, patches=PATCHES) == ['bound-received-lengths']
    assert _equal_to(library, 'patched')


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
        apply_patches(library, patches=PATCHES)
    assert str(refused.value) == (
        '%s:%d: differs from what patch bound-received-lengths expects (another version of the '
        'library, or changed by hand): nothing is changed' % (socket_c, changed + 1))
    # ros.cpp, which the other patch would change, is as it was too.
    assert before == {path: open(os.path.join(library, path)).read() for path in FILES}
    assert _listing(library) == sorted(FILES)


def test_a_missing_file_is_named(library):
    os.unlink(os.path.join(library, 'mros-lib', 'api', 'ros.cpp'))
    with pytest.raises(GenmrosError) as refused:
        apply_patches(library, patches=PATCHES)
    assert str(refused.value) == '%s: cannot read: No such file or directory' % os.path.join(
        library, 'mros-lib/api/ros.cpp')
    assert filecmp.cmp(os.path.join(library, 'mros-lib/comm/socket.c'),
                       os.path.join(TREE, 'library', 'mros-lib/comm/socket.c'), shallow=False)
