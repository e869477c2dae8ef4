# SPDX-License-Identifier: BSD-3-Clause
"""rosdep/colcon-mros.yaml: with it among rosdep's sources, the keys a
package.xml names (genmros for catkin, rosidl_generator_mros2 for ament, and
colcon-mros) resolve to the Debian package debian/control builds, on Debian 12
and Ubuntu 22.04 and 24.04. rosdep reads only sources of its own
(ROSDEP_SOURCE_PATH: the project's file) and an empty rosdistro index, so
`rosdep update` needs no network."""

import os
import re
import subprocess

import pytest

from support.checkout import REPO

KEYS = ['genmros', 'rosidl_generator_mros2', 'colcon-mros']
PLATFORMS = ['debian:bookworm', 'ubuntu:jammy', 'ubuntu:noble']


@pytest.fixture(scope='module')
def rosdep_environment(tmp_path_factory):
    """An environment in which rosdep's only rules are the project's."""
    root = tmp_path_factory.mktemp('rosdep')
    sources = root / 'sources.list.d'
    sources.mkdir()
    (sources / '50-colcon-mros.list').write_text(
        'yaml file://%s\n' % os.path.join(REPO, 'rosdep', 'colcon-mros.yaml'))
    index = root / 'index-v4.yaml'
    index.write_text('%YAML 1.1\n---\ndistributions: {}\ntype: index\nversion: 4\n')
    environment = dict(os.environ, ROSDEP_SOURCE_PATH=str(sources), ROS_HOME=str(root / 'home'),
                       ROSDISTRO_INDEX_URL='file://%s' % index)
    updated = subprocess.run(['rosdep', 'update'], env=environment,
                             capture_output=True, text=True)
    assert updated.returncode == 0, updated.stdout + updated.stderr
    return environment


def _resolve(environment, key, platform):
    result = subprocess.run(['rosdep', 'resolve', key, '--os=%s' % platform],
                            env=environment, capture_output=True, text=True)
    return result.returncode, result.stdout.split()


def _debian_package():
    """The package debian/control builds that is not the transitional one."""
    with open(os.path.join(REPO, 'debian', 'control')) as stream:
        stanzas = stream.read().split('\n\n')
    names = [re.search(r'^Package: (\S+)$', stanza, re.M).group(1) for stanza in stanzas
             if stanza.startswith('Package:') and 'Section: oldlibs' not in stanza]
    assert len(names) == 1, names
    return names[0]


@pytest.mark.parametrize('platform', PLATFORMS)
@pytest.mark.parametrize('key', KEYS)
def test_each_key_resolves_to_the_debian_package(rosdep_environment, key, platform):
    assert _resolve(rosdep_environment, key, platform) == (0, ['#apt', _debian_package()])


def test_a_release_without_the_package_does_not_resolve(rosdep_environment):
    # Ubuntu 20.04 (Noetic) installs colcon-mros with pip (docs/install.md).
    returncode, _ = _resolve(rosdep_environment, 'genmros', 'ubuntu:focal')
    assert returncode != 0
