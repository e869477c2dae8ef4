# SPDX-License-Identifier: BSD-3-Clause
"""The version is written once, in Python (colcon_mros.__version__): the
catkin and ament manifests and the Debian changelog keep theirs, held equal
to it here, and the CMake version file of rosidl_generator_mros2 is written
from it at install."""

import os
import re

from checkout_install import checkout_install
from conftest import REPO, run_genmros

from colcon_mros import __version__

MANIFESTS = [os.path.join(REPO, 'share', package, 'package.xml')
             for package in ('genmros', 'rosidl_generator_mros2')]
VERSION_FILE = os.path.join('share', 'rosidl_generator_mros2', 'cmake',
                            'rosidl_generator_mros2Config-version.cmake')


def test_genmros_says_the_packages_version():
    assert run_genmros('--version').stdout == 'genmros %s\n' % __version__


def test_the_catkin_and_ament_manifests_carry_the_version():
    # catkin and ament read the version from package.xml, which cannot take
    # it from Python.
    for manifest in MANIFESTS:
        with open(manifest) as stream:
            assert re.search(r'<version>([^<]*)</version>', stream.read()).group(1) == __version__


def test_the_installed_cmake_version_file_is_written_from_it():
    with open(os.path.join(checkout_install().prefix, VERSION_FILE)) as stream:
        text = stream.read()
    assert 'set(PACKAGE_VERSION "%s")' % __version__ in text
    assert '@' not in text
    # The source tree holds only its template.
    assert not os.path.exists(os.path.join(REPO, VERSION_FILE))


def test_the_debian_changelog_carries_the_version():
    with open(os.path.join(REPO, 'debian', 'changelog')) as stream:
        first = stream.readline()
    assert re.match(r'^colcon-mros \(([^)]+)\) ', first).group(1) == __version__
