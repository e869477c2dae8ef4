# SPDX-License-Identifier: BSD-3-Clause
"""This checkout: its paths, and genmros run from it as users run it."""

import os
import subprocess
import sys

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
TESTS = os.path.join(REPO, 'tests')
FIXTURES = os.path.join(TESTS, 'fixtures')
TEST_WS = os.path.join(REPO, 'test_ws')


def run_genmros(*arguments, check=True):
    """Run genmros from this checkout as users run it; returns the CompletedProcess."""
    result = subprocess.run([sys.executable, '-m', 'colcon_mros'] + list(arguments),
                            capture_output=True, text=True, cwd=REPO)
    if check and result.returncode != 0:
        raise AssertionError('genmros %s failed:\n%s' % (' '.join(arguments), result.stderr))
    return result
