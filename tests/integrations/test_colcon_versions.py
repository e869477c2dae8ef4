# SPDX-License-Identifier: BSD-3-Clause
"""The colcon hook (colcon_mros/integrations/colcon_argument_parser.py) under each colcon-core we
support: Debian's 0.12 (/usr/bin/colcon, with the Debian package of this
project) and the newest on PyPI, installed here into a venv that sees
Debian's colcon extensions, with this project installed into it as well.
The hook leans on how colcon-core sets a verb's defaults; this is where a
colcon-core release that changes that would show."""

import os
import shutil
import subprocess

import pytest

from support.checkout import TEST_WS
from support.build_integration import run, user_environment
from support.user_install import copy_sources, pip_flags

pytestmark = pytest.mark.slow


@pytest.fixture(scope='module')
def colcons(tmp_path_factory):
    root = str(tmp_path_factory.mktemp('colcon_versions'))
    venv = os.path.join(root, 'venv')
    subprocess.run(['/usr/bin/python3', '-m', 'venv', '--system-site-packages', venv], check=True)
    python = os.path.join(venv, 'bin', 'python')
    pip = [python, '-m', 'pip', 'install', '--quiet']
    subprocess.run(pip + ['--upgrade', 'colcon-core'], check=True, capture_output=True)
    subprocess.run(pip + pip_flags() + [copy_sources(root)], check=True, capture_output=True)
    return {'debian': ('/usr/bin/python3', user_environment()),
            'newest': (python,
                       user_environment(PATH=os.path.join(venv, 'bin') + ':/usr/bin:/bin'))}


def _version(python, environment):
    return subprocess.run([python, '-c', 'import colcon_core; print(colcon_core.__version__)'],
                          env=environment, capture_output=True, text=True,
                          check=True).stdout.strip()


def test_the_versions_are_debians_and_a_newer_one(colcons):
    debian, newest = (_version(*colcons[name]) for name in ('debian', 'newest'))
    assert debian.startswith('0.12.')
    assert tuple(map(int, newest.split('.')[:2])) > (0, 12)


@pytest.mark.parametrize('version', ['debian', 'newest'])
def test_build_exports_with_the_flag_and_only_with_it(colcons, version, tmp_path):
    python, environment = colcons[version]
    colcon = [python, '-m', 'colcon']
    assert '--mros-export DIR' in run(colcon + ['build', '--help'], str(tmp_path),
                                      environment).stdout
    workspace = str(tmp_path / 'ws')
    shutil.copytree(os.path.join(TEST_WS, 'src', 'mros_test_base'),
                    os.path.join(workspace, 'src', 'mros_test_base'))
    run(colcon + ['build'], workspace, environment)
    assert not os.path.exists(os.path.join(workspace, 'export'))
    export = os.path.join(workspace, 'export')
    run(colcon + ['build', '--mros-export', export], workspace, environment)
    assert os.path.isfile(os.path.join(export, 'include', 'mros_test_base', 'Vector3i.h'))
    with open(os.path.join(export, 'mros_export.cmake')) as stream:
        assert '\n  mros_test_base/Vector3i\n' in stream.read()
