# SPDX-License-Identifier: BSD-3-Clause
"""rosdep/colcon-mros.yaml: with it among rosdep's sources, a package.xml that
depends on genmros resolves to the Debian package colcon-mros, which the
set-up installed. rosdep runs on sources of its own (ROSDEP_SOURCE_PATH) and
an empty rosdistro index, so it reads nothing from the network."""

import os
import subprocess

from support.checkout import REPO

PACKAGE_XML = '''<?xml version="1.0"?>
<package format="2">
  <name>firmware_msgs</name>
  <version>0.0.1</version>
  <description>A firmware's message package.</description>
  <maintainer email="dev@colcon-mros.invalid">colcon-mros developers</maintainer>
  <license>BSD</license>
  <build_depend>genmros</build_depend>
</package>
'''


def _rosdep(environment, *arguments):
    result = subprocess.run(['rosdep'] + list(arguments) + ['--os=debian:bookworm'],
                            env=environment, capture_output=True, text=True)
    assert result.returncode == 0, result.stdout + result.stderr
    return result.stdout


def test_a_package_depending_on_genmros_resolves_to_the_installed_package(tmp_path):
    sources = tmp_path / 'sources.list.d'
    sources.mkdir()
    (sources / '50-colcon-mros.list').write_text(
        'yaml file://%s\n' % os.path.join(REPO, 'rosdep', 'colcon-mros.yaml'))
    index = tmp_path / 'index-v4.yaml'
    index.write_text('%YAML 1.1\n---\ndistributions: {}\ntype: index\nversion: 4\n')
    package = tmp_path / 'src' / 'firmware_msgs'
    package.mkdir(parents=True)
    (package / 'package.xml').write_text(PACKAGE_XML)
    environment = dict(os.environ, ROSDEP_SOURCE_PATH=str(sources),
                       ROS_HOME=str(tmp_path / 'home'),
                       ROSDISTRO_INDEX_URL='file://%s' % index)
    subprocess.run(['rosdep', 'update'], env=environment, check=True, capture_output=True)
    assert _rosdep(environment, 'resolve', 'genmros').split() == ['#apt', 'colcon-mros']
    assert _rosdep(environment, 'resolve', 'colcon-mros').split() == ['#apt', 'colcon-mros']
    checked = _rosdep(environment, 'check', '--from-paths', str(tmp_path / 'src'), '--ignore-src')
    assert checked.strip() == 'All system dependencies have been satisfied'
