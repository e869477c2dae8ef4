# SPDX-License-Identifier: BSD-3-Clause
"""Interface packages built with CMake against the rosidl of a venv of ROS 2
wheels (scripts/setup.sh --tests: Kilted's build/ros2-wheels, Jazzy's
build/ros2-wheels-jazzy), with this checkout's rosidl_generator_mros2: the
CMake package and support headers of its install
(support/checkout_install.py), and the checkout's entry point run by the
venv's Python."""

import collections
import os
import subprocess

import pytest

from support.checkout import REPO
from support.checkout_install import checkout_install


def venv_python(venv):
    return os.path.join(venv, 'bin', 'python')


def require_venv(venv):
    """Fails the test, saying how to make it, where venv is missing."""
    if not os.path.isfile(venv_python(venv)):
        pytest.fail('no %s: run scripts/setup.sh --tests' % venv)


def installed_version(venv, distribution):
    """The version of distribution installed in venv."""
    return subprocess.run([venv_python(venv), '-c', 'import importlib.metadata as m; '
                           'print(m.version(%r))' % distribution],
                          capture_output=True, text=True, check=True).stdout.strip()


def mros2_include(install, package):
    """The package's mros2 include root: <install>/include/<pkg>/mros2."""
    return os.path.join(str(install), 'include', package, 'mros2')


# An interface package built: its build and install dirs, and what its
# build step printed (the generator's notices among it).
InterfaceBuild = collections.namedtuple('InterfaceBuild', 'build install log')


def _run(argv, env):
    result = subprocess.run(argv, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            text=True)
    assert result.returncode == 0, ' '.join(argv) + '\n' + result.stdout[-6000:]
    return result.stdout


def build_interface_package(source, root, venv, prefixes=()):
    """source configured, built and installed with CMake in root (root/build,
    root/install), the venv first on CMAKE_PREFIX_PATH and AMENT_PREFIX_PATH
    (venv None: Debian's rosidl, in /usr) and prefixes after it (the
    installs of the packages it depends on, a prefix with the generator's
    ament index entry); an InterfaceBuild."""
    python = '/usr/bin/python3' if venv is None else venv_python(venv)
    generator = os.path.join(str(root), 'rosidl_generator_mros2')
    os.makedirs(str(root), exist_ok=True)
    with open(generator, 'w') as stream:
        stream.write('#!/bin/sh\nPYTHONPATH=%s exec %s -m '
                     'colcon_mros.integrations.rosidl_generator "$@"\n' % (REPO, python))
    os.chmod(generator, 0o755)
    search_path = ([] if venv is None else [venv]) + [str(prefix) for prefix in prefixes]
    env = {key: value for key, value in os.environ.items()
           if key not in ('AMENT_PREFIX_PATH', 'CMAKE_PREFIX_PATH', 'PYTHONPATH')}
    env['PATH'] = '/usr/bin:/bin' if venv is None else '%s:/usr/bin:/bin' % os.path.join(
        venv, 'bin')
    if search_path:
        env['AMENT_PREFIX_PATH'] = ':'.join(search_path)
    extension_dir = os.path.join(checkout_install().prefix, 'share', 'rosidl_generator_mros2',
                                 'cmake')
    build, install = os.path.join(str(root), 'build'), os.path.join(str(root), 'install')
    _run(['cmake', '-S', str(source), '-B', build,
          '-DCMAKE_PREFIX_PATH=%s' % ';'.join(search_path),
          '-DPython3_EXECUTABLE=%s' % python,
          '-Drosidl_generator_mros2_DIR=%s' % extension_dir,
          '-Drosidl_generator_mros2_BIN=%s' % generator, '-DCMAKE_INSTALL_PREFIX=%s' % install],
         env)
    log = _run(['cmake', '--build', build, '-j2'], env)
    _run(['cmake', '--install', build], env)
    return InterfaceBuild(build, install, log)
