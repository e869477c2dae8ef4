# SPDX-License-Identifier: BSD-3-Clause
"""cmake/genmros-names.cmake is what scripts/make-cmake-names.py writes: the names
the CMake module and the catkin generator use come from Python, and neither
CMake file spells them again."""

import os
import re
import subprocess
import sys

from support.checkout import REPO

CMAKE_FILES = [os.path.join(REPO, 'cmake', 'mros_generate.cmake'),
               os.path.join(REPO, 'share', 'genmros', 'cmake', 'genmros-extras.cmake')]


def _code(path):
    """path's CMake code without its comments."""
    with open(path) as stream:
        return re.sub(r'#[^\n]*', '', stream.read())


def test_the_committed_names_file_is_the_scripts_output():
    with open(os.path.join(REPO, 'cmake', 'genmros-names.cmake')) as stream:
        committed = stream.read()
    script = os.path.join(REPO, 'scripts', 'make-cmake-names.py')
    check = subprocess.run([sys.executable, script, '--check'], capture_output=True, text=True)
    assert (check.returncode, check.stderr) == (0, '')
    assert 'set(GENMROS_SERVICE_HALVES "Request;Response")' in committed


def test_the_names_check_sees_a_stale_file(tmp_path):
    # The script run from a copy of the checkout whose names file is stale.
    for tree in ('colcon_mros', 'scripts', 'cmake'):
        subprocess.run(['cp', '-r', os.path.join(REPO, tree), str(tmp_path)], check=True)
    names = tmp_path / 'cmake' / 'genmros-names.cmake'
    names.write_text(names.read_text().replace('Request;Response', 'Request'))
    script = str(tmp_path / 'scripts' / 'make-cmake-names.py')
    check = subprocess.run([sys.executable, script, '--check'], capture_output=True, text=True)
    assert check.returncode == 1
    assert check.stderr == '%s differs from the names in colcon_mros: run %s\n' % (names, script)
    assert subprocess.run([sys.executable, script], check=True).returncode == 0
    assert 'set(GENMROS_SERVICE_HALVES "Request;Response")' in names.read_text()


def test_the_cmake_files_take_the_names_from_it():
    for path in CMAKE_FILES:
        code = _code(path)
        for name in ('mros_message_support.h', 'message_headers.h', 'msg_max_size.h',
                     'Request', 'Response'):
            assert name not in code, '%s spells %s' % (path, name)
    assert '${GENMROS_SERVICE_HALVES}' in _code(CMAKE_FILES[1])
    assert '${GENMROS_FIRMWARE_AGGREGATES}' in _code(CMAKE_FILES[0])
