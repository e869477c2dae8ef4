# SPDX-License-Identifier: BSD-3-Clause
"""genmros where genmsg cannot be imported (an unsourced ROS Noetic shell, a
pyenv or conda python3 first on PATH): one line saying what to install or
source, no traceback, and --help and the colcon extension still load."""

import subprocess
import sys

from support.checkout import REPO, TEST_WS

# This interpreter, with genmsg made unimportable (as in a Python without it).
WITHOUT_GENMSG = "import sys; sys.modules['genmsg'] = None; sys.path.insert(0, %r); " % REPO


def _genmros_without_genmsg(*arguments):
    program = WITHOUT_GENMSG + 'from colcon_mros.cli import main; sys.exit(main(sys.argv[1:]))'
    return subprocess.run([sys.executable, '-c', program] + list(arguments),
                          capture_output=True, text=True)


def test_help_needs_no_genmsg():
    result = _genmros_without_genmsg('--help')
    assert result.returncode == 0 and 'genmros mros-v1-export' in result.stdout
    result = _genmros_without_genmsg('mros-v1-export', '--help')
    assert result.returncode == 0 and '--storage' in result.stdout


def test_generating_without_genmsg_says_what_to_do():
    for arguments in (['mros-v1-export', '--workspace', TEST_WS, '-o', '/tmp/unused'],
                      ['generate', TEST_WS + '/src/mros_test/msg/PersonalData.msg',
                       '-p', 'mros_test', '-o', '/tmp/unused']):
        result = _genmros_without_genmsg(*arguments)
        assert result.returncode == 1
        assert result.stderr.splitlines() == [
            'genmros: error: %s cannot import genmsg; install or source genmsg '
            '(Debian: apt-get install python3-genmsg; ROS Noetic: source '
            '/opt/ros/noetic/setup.bash), or run genmros with the Python that has it'
            % sys.executable]


def test_colcon_extension_loads_without_genmsg():
    # colcon loads every extension for every command: it must not need genmsg to load.
    result = subprocess.run([sys.executable, '-c', WITHOUT_GENMSG
                             + 'import colcon_mros.integrations.colcon_argument_parser'],
                            capture_output=True, text=True)
    assert result.returncode == 0, result.stderr
