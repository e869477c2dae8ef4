# SPDX-License-Identifier: BSD-3-Clause
"""The spellings this release replaced, kept until the next one: each still
does what its new spelling does, is hidden from --help, and says the new
spelling in one line on stderr."""

import os
import re

import pytest

from colcon_mros.cli import build_parser, main
from support.checkout import TEST_WS
from testing.ros_paths import prefix_arguments, ros1_prefixes

NEXT_RELEASE = '; the old name goes in the next release\n'


def _tree(root):
    """{relative path: text} of the files under root."""
    files = {}
    for directory, _, names in os.walk(root):
        for name in names:
            path = os.path.join(directory, name)
            with open(path) as stream:
                files[os.path.relpath(path, root)] = stream.read()
    return files


def test_export_is_mros_v1_export(tmp_path, capsys):
    arguments = ['--workspace', TEST_WS, '--type', 'mros_test/PersonalData']
    assert main(['mros-v1-export', *arguments, '-o', str(tmp_path / 'new')]) == 0
    capsys.readouterr()
    assert main(['export', *arguments, '-o', str(tmp_path / 'old')]) == 0
    assert capsys.readouterr().err == (
        "genmros: 'export' is now 'mros-v1-export'" + NEXT_RELEASE)
    assert _tree(str(tmp_path / 'old')) == _tree(str(tmp_path / 'new')) != {}


def test_prune_export_is_mros_v1_prune_export(tmp_path, capsys):
    source = tmp_path / 'demo' / 'msg' / 'Dropped.msg'
    source.parent.mkdir(parents=True)
    source.write_text('uint8 level\n')
    export_dir = tmp_path / 'export'
    assert main(['generate', str(source), '-p', 'demo', '-o', str(tmp_path / 'devel' / 'demo'),
                 '-I', 'demo:%s' % source.parent, '--add-to-export-dir', str(export_dir)]) == 0
    # What catkin does when Dropped.msg leaves its package.
    os.remove(export_dir / '.genmros' / 'claims' / 'demo' / 'msg' / 'Dropped.msg')
    capsys.readouterr()
    assert main(['prune-export', str(export_dir)]) == 0
    out, err = capsys.readouterr()
    assert err == "genmros: 'prune-export' is now 'mros-v1-prune-export'" + NEXT_RELEASE
    assert 'genmros: removed %s' % (export_dir / 'include' / 'demo' / 'Dropped.h') in \
        out.splitlines()
    assert not (export_dir / 'include' / 'demo' / 'Dropped.h').exists()


def test_mros2_pc_ros_is_mros2_pc_ros(tmp_path, monkeypatch, capsys):
    # No board runs for this state directory: both ask for one, the same way.
    monkeypatch.setenv('XDG_RUNTIME_DIR', str(tmp_path))
    assert main(['mros2-pc-ros', '--', 'true']) == 1
    new = capsys.readouterr().err
    assert new.startswith('genmros: error: no board runs')
    assert main(['mros2-pc', 'ros', '--', 'true']) == 1
    assert capsys.readouterr().err == (
        "genmros: 'mros2-pc ros' is now 'mros2-pc-ros'" + NEXT_RELEASE + new)


@pytest.mark.parametrize('subcommand, old, new, said', [
    ('mros-v1-pc', ['app', '--mros-root', 'mROS'], ['app', '--mros-v1-root', 'mROS'],
     "'--mros-root' is now '--mros-v1-root'"),
    ('mros-v1-fit', ['app', '--mros-root', 'mROS'], ['app', '--mros-v1-root', 'mROS'],
     "'--mros-root' is now '--mros-v1-root'"),
    ('mros-v1-pc', ['app', '--run'], ['app'],
     "'--run' is now the default ('--build-only' builds without running)"),
    ('mros-v1-harden', ['mROS', '--check'], ['--mros-v1-root', 'mROS', '--check'],
     "'mros-v1-harden DIR' is now 'mros-v1-harden --mros-v1-root DIR'"),
    ('mros2-harden', ['mros2', '--revert'], ['--mros2-root', 'mros2', '--revert'],
     "'mros2-harden DIR' is now 'mros2-harden --mros2-root DIR'"),
    ('mros2-peer-profile', ['--max-message', '1472', '--max-message', '1400'],
     ['--peer-max-message', '1400'], "'--max-message' is now '--peer-max-message'"),
], ids=lambda value: ' '.join(value) if isinstance(value, list) else None)
def test_an_old_option_spelling_asks_for_what_the_new_one_does(subcommand, old, new, said,
                                                               capsys):
    parser = build_parser()[1][subcommand]
    expected = vars(parser.parse_args(new))
    assert capsys.readouterr().err == ''
    assert vars(build_parser()[1][subcommand].parse_args(old)) == expected
    # Once, however often it is given.
    assert capsys.readouterr().err == 'genmros: %s%s' % (said, NEXT_RELEASE)


def test_msg_path_takes_source_trees_and_prefixes_as_workspace_and_prefix_do(tmp_path, capsys):
    prefixes = ros1_prefixes()
    arguments = ['--type', 'mros_test/PersonalData', '--type', 'sensor_msgs/JointState']
    assert main(['mros-v1-export', *arguments, '--workspace', TEST_WS,
                 *prefix_arguments(prefixes), '-o', str(tmp_path / 'new')]) == 0
    capsys.readouterr()
    assert main(['mros-v1-export', *arguments, '--msg-path', TEST_WS,
                 *[argument for prefix in prefixes for argument in ('--msg-path', prefix)],
                 '-o', str(tmp_path / 'old')]) == 0
    assert capsys.readouterr().err == (
        "genmros: '--msg-path' is now '--workspace' (a source tree) or '--prefix' (an installed "
        "prefix, with share/)" + NEXT_RELEASE)
    assert _tree(str(tmp_path / 'old')) == _tree(str(tmp_path / 'new')) != {}


OLD_OPTIONS = re.compile(r'--mros-root\b|--max-message\b|--run\b|--msg-path\b')


@pytest.mark.parametrize('subcommand', sorted(build_parser()[1]))
def test_no_help_names_an_old_spelling(subcommand, capsys):
    with pytest.raises(SystemExit):
        main([subcommand, '--help'])
    assert OLD_OPTIONS.findall(capsys.readouterr().out) == []
