# SPDX-License-Identifier: BSD-3-Clause
"""The version is written once, in Python (colcon_mros.__version__): the
catkin and ament manifests and the Debian changelog keep theirs, held equal
to it here, and the CMake version files of genmros and rosidl_generator_mros2
are written from it at install: find_package(genmros 0.1) works."""

import os
import re
import subprocess

from support.checkout_install import checkout_install
from support.checkout import REPO, run_genmros

from colcon_mros import __version__

MANIFESTS = [os.path.join(REPO, 'share', package, 'package.xml')
             for package in ('genmros', 'rosidl_generator_mros2')]
VERSION_FILES = [
    os.path.join('share', 'rosidl_generator_mros2', 'cmake',
                 'rosidl_generator_mros2Config-version.cmake'),
    os.path.join('share', 'genmros', 'cmake', 'genmrosConfig-version.cmake'),
    os.path.join('share', 'genmros', 'catkin_prefix', 'share', 'genmros', 'cmake',
                 'genmros-config-version.cmake')]


def test_genmros_says_the_packages_version():
    assert run_genmros('--version').stdout == 'genmros %s\n' % __version__


def test_the_catkin_and_ament_manifests_carry_the_version():
    # catkin and ament read the version from package.xml, which cannot take
    # it from Python.
    for manifest in MANIFESTS:
        with open(manifest) as stream:
            assert re.search(r'<version>([^<]*)</version>', stream.read()).group(1) == __version__


def test_the_installed_cmake_version_files_are_written_from_it():
    for version_file in VERSION_FILES:
        with open(os.path.join(checkout_install().prefix, version_file)) as stream:
            text = stream.read()
        assert 'set(PACKAGE_VERSION "%s")' % __version__ in text
        assert '@' not in text
        # The source tree holds only their template.
        assert not os.path.exists(os.path.join(REPO, version_file))


def test_find_package_takes_a_version(tmp_path):
    major_minor = '.'.join(__version__.split('.')[:2])
    (tmp_path / 'CMakeLists.txt').write_text(
        'cmake_minimum_required(VERSION 3.16)\nproject(firmware NONE)\n'
        'find_package(genmros %s REQUIRED)\nmessage(STATUS "genmros ${genmros_VERSION}")\n'
        'find_package(genmros 99.0 QUIET)\nmessage(STATUS "99.0 found: ${genmros_FOUND}")\n'
        % major_minor)
    result = subprocess.run(['cmake', '-S', str(tmp_path), '-B', str(tmp_path / 'build')],
                            env=checkout_install().environment(os.environ),
                            capture_output=True, text=True)
    assert result.returncode == 0, result.stdout + result.stderr
    assert '-- genmros %s\n' % __version__ in result.stdout
    assert '-- 99.0 found: 0\n' in result.stdout


def test_the_debian_changelog_carries_the_version():
    with open(os.path.join(REPO, 'debian', 'changelog')) as stream:
        first = stream.readline()
    assert re.match(r'^colcon-mros \(([^)]+)\) ', first).group(1) == __version__
