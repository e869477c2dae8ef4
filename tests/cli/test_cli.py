# SPDX-License-Identifier: BSD-3-Clause
"""colcon_mros.cli: every subcommand the parser has answers --help; a command
line names its subcommand, and an unknown one is named as unknown."""

import re

import pytest

from colcon_mros.cli import SUBCOMMAND_GROUPS, build_parser, main

SUBCOMMANDS = list(build_parser()[1])
USER_SUBCOMMANDS = [name for _, names in SUBCOMMAND_GROUPS for name in names]
# What catkin runs: it answers --help, but the top-level help leaves it out.
PLUMBING = ['generate', 'catkin-export-dir']


def test_the_parser_has_the_subcommands_the_docs_describe():
    assert len(SUBCOMMANDS) >= 10 and {
        'generate', 'mros-v1-export', 'mros-v1-pc', 'mros-v1-fit'} <= set(SUBCOMMANDS)


@pytest.mark.parametrize('subcommand', SUBCOMMANDS)
def test_every_subcommand_has_help(subcommand, capsys):
    with pytest.raises(SystemExit) as done:
        main([subcommand, '--help'])
    assert done.value.code == 0
    assert capsys.readouterr().out.startswith('usage: genmros %s' % subcommand)


def test_top_level_help_groups_the_users_subcommands_and_hides_the_plumbing(capsys):
    with pytest.raises(SystemExit):
        main(['--help'])
    out = capsys.readouterr().out
    assert sorted(USER_SUBCOMMANDS + PLUMBING) == sorted(SUBCOMMANDS)
    groups = out[out.index('mROS v1 (ROS 1):'):]
    listed = [line.split()[0] for line in groups.splitlines()
              if line.startswith('  ') and not line.startswith('   ')]
    assert listed == USER_SUBCOMMANDS
    headings = groups[:groups.index('Every subcommand')].splitlines()
    assert [line for line in headings if line and not line.startswith(' ')] == [
        'mROS v1 (ROS 1):', 'mros2 (ROS 2):', 'paths for builds:']
    for plumbing in PLUMBING:
        assert '\n  %s ' % plumbing not in out and 'genmros %s' % plumbing not in out


@pytest.mark.parametrize('subcommand, old, new', [
    ('mros-v1-export', '--underlay', '--prefix'), ('mros-v1-export', '--msg-path', '--prefix'),
    ('mros2-export', '--msg-path', '--prefix'), ('mros-v1-fit', '--underlay', '--prefix')])
def test_old_option_names_are_hidden_aliases(subcommand, old, new, capsys):
    with pytest.raises(SystemExit):
        main([subcommand, '--help'])
    help_text = capsys.readouterr().out
    assert '--workspace WS' in help_text and '%s PREFIX' % new in help_text
    assert '--underlay' not in help_text and '--msg-path' not in help_text
    parser = build_parser()[1][subcommand]
    required = ['-o', 'out'] if subcommand.endswith('export') else []
    options = parser.parse_args(required + [old, '/somewhere'])
    assert '/somewhere' in (options.prefixes or []) + options.msg_paths


def test_one_name_for_each_kind_of_place_on_every_subcommand(capsys):
    for subcommand in ('mros-v1-export', 'mros-v1-fit', 'mros-v1-pc', 'mros2-export',
                       'mros2-fit'):
        with pytest.raises(SystemExit):
            main([subcommand, '--help'])
        help_text = capsys.readouterr().out
        assert '--workspace WS' in help_text and '--prefix PREFIX' in help_text, subcommand


def test_no_arguments_is_one_line_and_exit_2(capsys):
    assert main([]) == 2
    assert capsys.readouterr().err.splitlines()[-1] == (
        'genmros: error: give a subcommand (genmros --help lists them)')


@pytest.mark.parametrize('argv', [['exprot', '-o', 'out'],
                                  ['Missing.msg', '-p', 'demo', '-o', 'x']])
def test_an_unknown_subcommand_is_named_with_the_list(argv, capsys):
    assert main(argv) == 2
    assert capsys.readouterr().err.splitlines()[-1] == (
        "genmros: error: unknown subcommand '%s' (the subcommands: %s)"
        % (argv[0], ', '.join(USER_SUBCOMMANDS)))


def test_generate_reads_its_files(tmp_path, capsys):
    assert main(['generate', str(tmp_path / 'Missing.msg'), '-p', 'demo', '-o',
                 str(tmp_path / 'out')]) == 1
    assert capsys.readouterr().err.startswith('genmros: error: %s: cannot read file'
                                              % (tmp_path / 'Missing.msg'))


def test_a_misspelt_option_is_refused_with_the_subcommand_s_usage(capsys):
    with pytest.raises(SystemExit) as done:
        main(['mros-v1-export', '--workspce', 'ws', '-o', 'out'])
    assert done.value.code == 2
    error = capsys.readouterr().err.splitlines()
    assert error[0].startswith('usage: genmros mros-v1-export ')
    assert error[-1] == 'genmros mros-v1-export: error: unrecognized arguments: --workspce ws'


def test_an_option_name_means_one_thing_in_every_subcommand(capsys):
    # --export-dir names an export dir to read (mros-v1-export, mros-v1-fit);
    # generate's output dir is --add-to-export-dir, its old name a hidden alias.
    with pytest.raises(SystemExit):
        main(['generate', '--help'])
    help_text = capsys.readouterr().out
    assert '--add-to-export-dir DIR' in help_text and '--export-dir' not in help_text
    generate = build_parser()[1]['generate']
    for name in ('--add-to-export-dir', '--export-dir'):
        options = generate.parse_args(['A.msg', '-p', 'demo', '-o', 'out', name, 'exports'])
        assert options.export_dir == 'exports'
    for subcommand in ('mros-v1-export', 'mros-v1-fit'):
        with pytest.raises(SystemExit):
            main([subcommand, '--help'])
        assert 'the types come from' in ' '.join(capsys.readouterr().out.split())


@pytest.mark.parametrize('flags, runs', [([], True), (['--build-only'], False)])
def test_mros_v1_pc_builds_and_runs_unless_build_only(flags, runs, monkeypatch, capsys):
    from colcon_mros.library_tools.mros_v1.pc_target import build
    ran = []
    monkeypatch.setattr(build, 'build', lambda request: '/built/%s' % request.app_dir)
    monkeypatch.setattr(build, 'run_program', lambda *program: ran.append(program))
    assert main(['mros-v1-pc', 'app', '--target', 'native'] + flags) == 0
    assert capsys.readouterr().out.startswith('genmros: built /built/app\n')
    assert ran == ([('/built/app', 'native')] if runs else [])


@pytest.mark.parametrize('subcommand, written', [
    ('generate', "the package's header directory"), ('mros-v1-export', 'the include root'),
    ('mros2-export', 'the include root'), ('mros-v1-pc', 'the build directory'),
    ('mros2-pc', 'the build directory'), ('mros2-peer-profile', 'the profile file')])
def test_output_names_what_the_subcommand_writes(subcommand, written, capsys):
    with pytest.raises(SystemExit):
        main([subcommand, '--help'])
    help_text = ' '.join(capsys.readouterr().out.split())
    assert re.search(r'-o (DIR|FILE), --output (DIR|FILE) %s' % re.escape(written), help_text)
