"""colcon_mros.library_tools.mros_v1.patches: the opt-in patch set for a user's mROS v1
library, applied to copies of the real checkout's mros-lib (MROS_V1_ROOT)
with genmros mros-v1-harden, as a user applies it to theirs."""

import filecmp
import os
import shutil
import subprocess

import pytest

from colcon_mros.errors import GenmrosError
from colcon_mros.library_tools.mros_v1.patches import MROS_V1_SERIES, mros_v1_patches
from colcon_mros.library_tools.patch_series import apply_patches, read_patch
from support.checkout import run_genmros
from support.user_checkouts import MROS_V1_ROOT

PATCH_DIR = MROS_V1_SERIES.directory

pytestmark = [pytest.mark.needs_mros_v1]


@pytest.fixture
def checkout(tmp_path):
    """A copy of the checkout's mros-lib (what the patches touch) and one
    sample app, which they must not."""
    shutil.copytree(os.path.join(MROS_V1_ROOT, 'mros-lib'), str(tmp_path / 'mros-lib'))
    shutil.copytree(os.path.join(MROS_V1_ROOT, 'mros_ws', 'string_pubsub'),
                    str(tmp_path / 'mros_ws' / 'string_pubsub'))
    return tmp_path


def _same_as_original(root):
    comparison = filecmp.dircmp(os.path.join(MROS_V1_ROOT, 'mros-lib'), str(root / 'mros-lib'))

    def differing(node):
        return node.diff_files + node.left_only + node.right_only + [
            name for child in node.subdirs.values() for name in differing(child)]
    return differing(comparison)


def _touched_files():
    return sorted({path for patch in mros_v1_patches() for path in patch.files})


def test_apply_check_revert_on_a_checkout(checkout):
    names = [patch.name for patch in mros_v1_patches()]
    assert names and all(patch.description for patch in mros_v1_patches())
    before = run_genmros('mros-v1-harden', '--mros-v1-root', str(checkout), '--check', check=False)
    assert before.returncode == 1
    assert before.stdout.splitlines() == [
        'not applied   %s: %s' % (patch.name, patch.description) for patch in mros_v1_patches()]

    applied = run_genmros('mros-v1-harden', '--mros-v1-root', str(checkout))
    assert applied.stdout == 'genmros: applied %s\n' % ', '.join(names)
    # Exactly the files the patches name changed, each containing its new lines.
    changed = sorted(os.path.join('mros-lib', path) for path in _same_as_original(checkout))
    assert sorted(os.path.basename(path) for path in _touched_files()) == sorted(
        os.path.basename(path) for path in changed)
    for patch in mros_v1_patches():
        texts = ''.join((checkout / path).read_text() for path in patch.files)
        with open(patch.path) as stream:
            added = [line[1:] for line in stream.read().splitlines()
                     if line.startswith('+') and not line.startswith('+++')]
        assert added and all(line in texts for line in added), patch.name
    assert not filecmp.dircmp(os.path.join(MROS_V1_ROOT, 'mros_ws', 'string_pubsub'),
                              str(checkout / 'mros_ws' / 'string_pubsub')).diff_files

    times = {path: os.stat(checkout / path).st_mtime_ns for path in _touched_files()}
    again = run_genmros('mros-v1-harden', '--mros-v1-root', str(checkout))
    assert again.stdout == 'genmros: nothing to do: the patches are in\n'
    assert times == {path: os.stat(checkout / path).st_mtime_ns for path in _touched_files()}
    checked = run_genmros('mros-v1-harden', '--mros-v1-root', str(checkout), '--check')
    assert checked.stdout.splitlines() == [
        'applied       %s: %s' % (patch.name, patch.description) for patch in mros_v1_patches()]

    reverted = run_genmros('mros-v1-harden', '--mros-v1-root', str(checkout), '--revert')
    assert reverted.stdout == 'genmros: took out %s\n' % ', '.join(reversed(names))
    assert _same_as_original(checkout) == []


def _first_hunk(patch):
    """(path, the line the first hunk starts at, its lines as the library has
    them) of a patch, read from its text."""
    with open(patch.path) as stream:
        lines = stream.read().splitlines()
    path = next(line[4:].split('/', 1)[1] for line in lines if line.startswith('+++ '))
    header = next(index for index, line in enumerate(lines) if line.startswith('@@ -'))
    start = int(lines[header].split()[1][1:].split(',')[0])
    body = []
    for line in lines[header + 1:]:
        if line.startswith('@@') or line.startswith('--- '):
            break
        if line[:1] in (' ', '-'):
            body.append(line[1:])
    return path, start, body


def test_a_checkout_that_differs_is_refused_and_left_as_it_is(checkout):
    # A line the last patch's first hunk expects, changed by hand.
    patch = mros_v1_patches()[-1]
    path, start, expected = _first_hunk(patch)
    lines = (checkout / path).read_text().splitlines(keepends=True)
    changed = start + next(index for index, line in enumerate(expected) if line.strip())
    lines[changed - 1] = '/* changed by hand */\n'
    (checkout / path).write_text(''.join(lines))
    result = run_genmros('mros-v1-harden', '--mros-v1-root', str(checkout), check=False)
    assert result.returncode == 1 and result.stdout == ''
    assert result.stderr == (
        'genmros: error: %s:%d: differs from what hunk #1 of patch %s expects from here on '
        '(another version of the library, or changed by hand): nothing is changed\n'
        % (checkout / path, start, patch.name))
    # The other patches, which would apply, were not applied either.
    assert _same_as_original(checkout) == [os.path.basename(path)]
    assert run_genmros('mros-v1-harden', '--mros-v1-root', str(checkout), '--check',
                       check=False).returncode == 1


def test_not_a_checkout(tmp_path):
    result = run_genmros('mros-v1-harden', '--mros-v1-root', str(tmp_path), check=False)
    assert result.returncode == 1
    assert result.stderr == 'genmros: error: %s: no mros-lib/ here: not an mROS v1 checkout\n' \
        % tmp_path


def test_a_patch_may_change_the_library_only(tmp_path):
    outside = tmp_path / 'outside.patch'
    outside.write_text('Changes an app.\n\n--- a/mros_ws/app/app.cpp\n+++ b/mros_ws/app/app.cpp\n'
                       '@@ -1,1 +1,1 @@\n-a\n+b\n')
    with pytest.raises(GenmrosError) as error:
        read_patch(str(outside), MROS_V1_SERIES.library_dirs)
    assert str(error.value) == '%s:4: patches may change mros-lib/ only, not mros_ws/app/app.cpp' \
        % outside


def test_every_patch_is_named_for_what_it_fixes_and_applies_alone(checkout):
    for name in sorted(os.listdir(PATCH_DIR)):
        if name.endswith('.patch'):
            assert name.replace('-', '').replace('.patch', '').isalpha(), name
    for patch in mros_v1_patches():
        # Each patch on its own, forward and back.
        assert apply_patches(str(checkout), [patch]) == [patch.name]
        assert apply_patches(str(checkout), [patch], revert=True) == [patch.name]
    assert _same_as_original(checkout) == []


def test_gnu_patch_applies_the_series_as_genmros_does(checkout, tmp_path):
    # The maintainers' tool, without fuzz, in the series' order.
    by_gnu_patch = tmp_path / 'gnu_patch'
    shutil.copytree(os.path.join(MROS_V1_ROOT, 'mros-lib'), str(by_gnu_patch / 'mros-lib'))
    for patch in mros_v1_patches():
        with open(os.path.join(PATCH_DIR, patch.name + '.patch'), 'rb') as stream:
            subprocess.run(['patch', '-p1', '--fuzz=0', '--batch', '--silent',
                            '--no-backup-if-mismatch'], stdin=stream, cwd=str(by_gnu_patch),
                           check=True)
    apply_patches(str(checkout), mros_v1_patches())
    comparison = filecmp.dircmp(str(checkout / 'mros-lib'), str(by_gnu_patch / 'mros-lib'))

    def differing(node):
        return node.diff_files + node.left_only + node.right_only + [
            name for child in node.subdirs.values() for name in differing(child)]
    assert differing(comparison) == []
