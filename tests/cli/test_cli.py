"""colcon_mros.cli: every subcommand answers --help; a command line without
one is generator mode, as catkin calls it."""

import pytest

from colcon_mros.cli import main

SUBCOMMANDS = ['generate', 'export', 'make-fragment', 'cmake-dir', 'catkin-prefix', 'prune-export',
               'catkin-export-dir', 'mros-v1-pc']


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
    assert 'genmros FILE.msg|FILE.srv -p PKG -o OUTDIR' in out
    for subcommand in SUBCOMMANDS:
        assert subcommand in out


def test_no_arguments_is_one_line_and_exit_2(capsys):
    assert main([]) == 2
    assert 'genmros: error: give a .msg or .srv file, or a subcommand' in capsys.readouterr().err


def test_a_file_without_subcommand_is_generator_mode(tmp_path, capsys):
    assert main([str(tmp_path / 'Missing.msg'), '-p', 'demo', '-o', str(tmp_path / 'out')]) == 1
    assert capsys.readouterr().err.startswith('genmros: error: %s: cannot read file' % (tmp_path / 'Missing.msg'))
