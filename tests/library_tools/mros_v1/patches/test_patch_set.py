"""colcon_mros.library_tools.mros_v1.patches: the opt-in patch set for a user's mROS v1
library, applied to copies of the real checkout's mros-lib (MROS_V1_ROOT)
with genmros mros-v1-harden, as a user applies it to theirs."""

import filecmp
import os
import shutil
import subprocess

import pytest

from colcon_mros.library_tools.mros_v1.patches import MROS_V1_SERIES, mros_v1_patches
from colcon_mros.library_tools.patch_series import apply_patches, read_patch

PATCH_DIR = MROS_V1_SERIES.directory
from colcon_mros.errors import GenmrosError
from conftest import run_genmros
from mros_v1_checkout import MROS_V1_ROOT

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
    before = run_genmros('mros-v1-harden', str(checkout), '--check', check=False)
    assert before.returncode == 1
    assert before.stdout.splitlines() == [
        'not applied   %s: %s' % (patch.name, patch.description) for patch in mros_v1_patches()]

    applied = run_genmros('mros-v1-harden', str(checkout))
    assert applied.stdout == 'genmros: applied %s\n' % ', '.join(names)
    # Exactly the files the patches name changed, each containing its new lines.
    changed = sorted(os.path.join('mros-lib', path) for path in _same_as_original(checkout))
    assert sorted(os.path.basename(path) for path in _touched_files()) == sorted(
        os.path.basename(path) for path in changed)
    for patch in mros_v1_patches():
        for path, hunks in patch.files.items():
            text = (checkout / path).read_text()
            for hunk in hunks:
                assert '\n'.join(hunk.new) in text, (patch.name, path)
    assert not filecmp.dircmp(os.path.join(MROS_V1_ROOT, 'mros_ws', 'string_pubsub'),
                              str(checkout / 'mros_ws' / 'string_pubsub')).diff_files

    times = {path: os.stat(checkout / path).st_mtime_ns for path in _touched_files()}
    again = run_genmros('mros-v1-harden', str(checkout))
    assert again.stdout == 'genmros: nothing to do: the patches are in\n'
    assert times == {path: os.stat(checkout / path).st_mtime_ns for path in _touched_files()}
    assert run_genmros('mros-v1-harden', str(checkout), '--check').stdout.splitlines() == [
        'applied       %s: %s' % (patch.name, patch.description) for patch in mros_v1_patches()]

    reverted = run_genmros('mros-v1-harden', str(checkout), '--revert')
    assert reverted.stdout == 'genmros: took out %s\n' % ', '.join(reversed(names))
    assert _same_as_original(checkout) == []


def test_a_checkout_that_differs_is_refused_and_left_as_it_is(checkout):
    # A line the last patch's hunk expects, changed by hand.
    patch = mros_v1_patches()[-1]
    path, hunks = sorted(patch.files.items())[0]
    lines = (checkout / path).read_text().splitlines(keepends=True)
    expected_line = hunks[0].old_start + next(
        index for index, line in enumerate(hunks[0].old) if line.strip())
    lines[expected_line - 1] = '/* changed by hand */\n'
    (checkout / path).write_text(''.join(lines))
    result = run_genmros('mros-v1-harden', str(checkout), check=False)
    assert result.returncode == 1 and result.stdout == ''
    assert result.stderr == (
        'genmros: error: %s:%d: differs from what patch %s expects (another version of the '
        'library, or changed by hand): nothing is changed\n'
        % (checkout / path, expected_line, patch.name))
    # The other patches, which would apply, were not applied either.
    assert _same_as_original(checkout) == [os.path.basename(path)]
    assert run_genmros('mros-v1-harden', str(checkout), '--check', check=False).returncode == 1


def test_not_a_checkout(tmp_path):
    result = run_genmros('mros-v1-harden', str(tmp_path), check=False)
    assert result.returncode == 1
    assert result.stderr == 'genmros: error: %s: no mros-lib/ here: not an mROS v1 checkout\n' \
        % tmp_path


def test_a_patch_may_change_the_library_only(tmp_path):
    outside = tmp_path / 'outside.patch'
    outside.write_text('Changes an app.\n\n--- a/mros_ws/app/app.cpp\n+++ b/mros_ws/app/app.cpp\n'
                       '@@ -1,1 +1,1 @@\n-a\n+b\n')
    with pytest.raises(GenmrosError) as error:
        read_patch(str(outside), MROS_V1_SERIES.library_dir)
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


def test_every_hunk_has_one_place_in_the_library():
    # A hunk that another patch moved is found by its lines; they must not
    # also fit somewhere else (where a change by hand would then land it).
    for patch in mros_v1_patches():
        for path, hunks in patch.files.items():
            with open(os.path.join(MROS_V1_ROOT, path), encoding='utf-8') as stream:
                lines = stream.read().splitlines()
            for hunk in hunks:
                places = [index + 1 for index in range(len(lines))
                          if lines[index:index + len(hunk.old)] == hunk.old]
                assert places == [hunk.old_start], (patch.name, path, places)


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

