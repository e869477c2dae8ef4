"""The patch set's mechanics (colcon_mros.library_tools.patch_series) on a small
tree of the tests' own (tests/fixtures/patch_tree): library/, copied to a
checkout's mros-lib/ for each test, two patches of its own, and patched/,
the same files with the fixes written by hand. Apply, check, revert, refusal
of a tree changed by hand, and whole-file writes; the real patch set on a real
checkout is test_patch_set.py's."""

import filecmp
import os
import shutil

import pytest

from colcon_mros.errors import GenmrosError
from colcon_mros.library_tools.patch_series import (PatchSeries, apply_patches, patch_states,
                                                    read_series)

from support.checkout import REPO

TREE = os.path.join(REPO, 'tests', 'fixtures', 'patch_tree')


def series_in(directory):
    """The patches of a series directory of the fixture's kind."""
    return read_series(PatchSeries(directory, ('mros-lib',)))


PATCHES = series_in(os.path.join(TREE, 'patches'))
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
        series_in(directory)
    assert str(refused.value) == '%s: patches not in the series: publish-without-memory.patch' \
        % os.path.join(directory, 'series')
    directory = _patch_dir(tmp_path / 'again', '# comment\nbound-received-lengths.patch\n'
                           'publish-without-memory.patch\nmissing.patch\n')
    with pytest.raises(GenmrosError) as refused:
        series_in(directory)
    assert str(refused.value) == '%s:4: missing.patch: no such patch' % os.path.join(
        directory, 'series')


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
    # The hunk of lines 11-16 holds the line changed (13).
    assert changed + 1 == 13
    assert str(refused.value) == (
        '%s:11: differs from what hunk #2 of patch bound-received-lengths expects from here on '
        '(another version of the library, or changed by hand): nothing is changed' % socket_c)
    # ros.cpp, which the other patch would change, is as it was too.
    assert before == {path: open(os.path.join(library, path)).read() for path in FILES}
    assert _listing(library) == sorted(FILES)


def test_a_missing_file_is_named(library):
    os.unlink(os.path.join(library, 'mros-lib', 'api', 'ros.cpp'))
    with pytest.raises(GenmrosError) as refused:
        apply_patches(library, PATCHES)
    assert str(refused.value) == (
        '%s: patch publish-without-memory changes this file, which is not there: nothing is '
        'changed' % os.path.join(library, 'mros-lib/api/ros.cpp'))
    assert filecmp.cmp(os.path.join(library, 'mros-lib/comm/socket.c'),
                       _fixture_file('library', 'mros-lib/comm/socket.c'), shallow=False)


def _series(tmp_path, **patches):
    """A series of its own: the patches in the order given."""
    directory = tmp_path / 'own-series'
    directory.mkdir()
    (directory / 'series').write_text(''.join('%s.patch\n' % name for name in patches))
    for name, text in patches.items():
        (directory / (name + '.patch')).write_text(text)
    return series_in(str(directory))


def test_a_patch_adds_and_removes_files_and_keeps_a_last_line_without_newline(library, tmp_path):
    socket_c = os.path.join(library, 'mros-lib', 'comm', 'socket.c')
    with open(socket_c, 'rb') as stream:
        original = stream.read()
    patches = _series(tmp_path, **{
        'add-a-header': ('Adds a header.\n\n'
                         '--- /dev/null\n+++ b/mros-lib/comm/limits.h\n@@ -0,0 +1,2 @@\n'
                         '+#define LIMIT 64\n+/* no newline at the end */\n'
                         '\\ No newline at end of file\n'),
        'drop-ros-cpp': '--- a/mros-lib/api/ros.cpp\n+++ /dev/null\n' + ''.join(
            ['@@ -1,%d +0,0 @@\n' % len(open(_fixture_file('library', 'mros-lib/api/ros.cpp'))
                                        .read().splitlines())]
            + ['-' + line + '\n' for line in open(_fixture_file('library', 'mros-lib/api/ros.cpp'))
               .read().splitlines()]),
    })
    assert apply_patches(library, patches) == ['add-a-header', 'drop-ros-cpp']
    with open(os.path.join(library, 'mros-lib', 'comm', 'limits.h'), 'rb') as stream:
        assert stream.read() == b'#define LIMIT 64\n/* no newline at the end */'
    assert not os.path.exists(os.path.join(library, 'mros-lib', 'api', 'ros.cpp'))
    assert [applied for _, applied in patch_states(library, patches)] == [True, True]
    assert apply_patches(library, patches, revert=True) == ['drop-ros-cpp', 'add-a-header']
    assert _equal_to(library, 'library')
    assert not os.path.exists(os.path.join(library, 'mros-lib', 'comm', 'limits.h'))
    with open(socket_c, 'rb') as stream:
        assert stream.read() == original


def test_a_hunk_that_only_adds_lines_lands_where_its_header_says(library, tmp_path):
    # No context at all: the added line goes after line 2, as GNU patch puts it.
    patches = _series(tmp_path, **{'note': (
        '--- a/mros-lib/comm/socket.c\n+++ b/mros-lib/comm/socket.c\n@@ -2,0 +3 @@\n'
        '+/* genmros: a note after line 2 */\n')})
    socket_c = os.path.join(library, 'mros-lib', 'comm', 'socket.c')
    with open(socket_c) as stream:
        lines = stream.readlines()
    assert apply_patches(library, patches) == ['note']
    with open(socket_c) as stream:
        assert stream.readlines() == lines[:2] + \
                                ['/* genmros: a note after line 2 */\n'] + lines[2:]


def test_taking_out_is_checked_as_putting_in(library):
    apply_patches(library, PATCHES)
    ros_cpp = os.path.join(library, 'mros-lib', 'api', 'ros.cpp')
    with open(ros_cpp) as stream:
        text = stream.read()
    # A line the first patch added, changed by hand after it went in.
    with open(ros_cpp, 'w') as stream:
        stream.write(text.replace('    return;\n', '    return; /* mine */\n', 1))
    before = {path: open(os.path.join(library, path)).read() for path in FILES}
    with pytest.raises(GenmrosError) as refused:
        apply_patches(library, PATCHES, revert=True)
    assert str(refused.value).startswith(ros_cpp + ':')
    assert 'hunk #1 of patch publish-without-memory' in str(refused.value)
    # socket.c, whose patch would have come out first, is as it was.
    assert before == {path: open(os.path.join(library, path)).read() for path in FILES}
    assert _listing(library) == sorted(FILES)
