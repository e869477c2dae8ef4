# SPDX-License-Identifier: BSD-3-Clause
"""flake8 (Debian's python3-flake8, setup.cfg's [flake8]: 99 columns) finds
nothing in the package, the test support, the main job, the benchmarks and
the tests, as colcon-core's suite holds its own code."""

import subprocess
import sys

from support.checkout import REPO

CHECKED = ['setup.py', 'colcon_mros', 'testing', 'evaluation', 'bench', 'scripts', 'tests']


def test_flake8_finds_nothing():
    result = subprocess.run([sys.executable, '-m', 'flake8'] + CHECKED, cwd=REPO,
                            capture_output=True, text=True)
    assert result.stderr == ''
    assert result.stdout == ''
    assert result.returncode == 0
