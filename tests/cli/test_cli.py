# SPDX-License-Identifier: BSD-3-Clause
"""colcon_mros.cli: every subcommand the parser has answers --help; a command
line names its subcommand, and an unknown one is named as unknown."""

import pytest

from colcon_mros.cli import build_parser, main

SUBCOMMANDS = list(build_parser()[1])


def test_the_parser_has_the_subcommands_the_docs_describe():
    assert len(SUBCOMMANDS) >= 10 and {'generate', 'export', 'mros-v1-pc', 'mros-v1-fit'} <= set(
        SUBCOMMANDS)


@pytest.mark.parametrize('subcommand', SUBCOMMANDS)
def test_every_subcommand_has_help(subcommand, capsys):
    with pytest.raises(SystemExit) as done:
        main([subcommand, '--help'])
    assert done.value.code == 0
    assert capsys.readouterr().out.startswith('usage: genmros %s' % subcommand)


def test_top_level_help_lists_the_subcommands(capsys):
    with pytest.raises(SystemExit):
        main(['--help'])
    out = capsys.readouterr().out
    assert 'genmros generate FILE.msg|FILE.srv -p PKG -o OUTDIR' in out
    for subcommand in SUBCOMMANDS:
        assert '\n    %s' % subcommand in out


def test_no_arguments_is_one_line_and_exit_2(capsys):
    assert main([]) == 2
    assert capsys.readouterr().err.splitlines()[-1] == (
        'genmros: error: give a subcommand (genmros --help lists them)')


@pytest.mark.parametrize('argv', [['exprot', '-o', 'out'], ['Missing.msg', '-p', 'demo', '-o', 'x']])
def test_an_unknown_subcommand_is_named_with_the_list(argv, capsys):
    assert main(argv) == 2
    assert capsys.readouterr().err.splitlines()[-1] == (
        "genmros: error: unknown subcommand '%s' (the subcommands: %s)"
        % (argv[0], ', '.join(SUBCOMMANDS)))


def test_generate_reads_its_files(tmp_path, capsys):
    assert main(['generate', str(tmp_path / 'Missing.msg'), '-p', 'demo', '-o',
                 str(tmp_path / 'out')]) == 1
    assert capsys.readouterr().err.startswith('genmros: error: %s: cannot read file'
                                              % (tmp_path / 'Missing.msg'))


def test_a_misspelt_option_is_refused_with_the_subcommand_s_usage(capsys):
    with pytest.raises(SystemExit) as done:
        main(['export', '--workspce', 'ws', '-o', 'out'])
    assert done.value.code == 2
    error = capsys.readouterr().err.splitlines()
    assert error[0].startswith('usage: genmros export ')
    assert error[-1] == 'genmros export: error: unrecognized arguments: --workspce ws'


def test_an_option_name_means_one_thing_in_every_subcommand(capsys):
    # --export-dir names an export dir to read (export, mros-v1-fit);
    # generate's output dir is --add-to-export-dir, its old name a hidden alias.
    with pytest.raises(SystemExit):
        main(['generate', '--help'])
    help_text = capsys.readouterr().out
    assert '--add-to-export-dir DIR' in help_text and '--export-dir' not in help_text
    generate = build_parser()[1]['generate']
    for name in ('--add-to-export-dir', '--export-dir'):
        options = generate.parse_args(['A.msg', '-p', 'demo', '-o', 'out', name, 'exports'])
        assert options.export_dir == 'exports'
    for subcommand in ('export', 'mros-v1-fit'):
        with pytest.raises(SystemExit):
            main([subcommand, '--help'])
        assert 'the types come from' in ' '.join(capsys.readouterr().out.split())
