# SPDX-License-Identifier: BSD-3-Clause
"""genmros in a ROS Noetic layout, simulated on this machine.

Ubuntu 20.04 + Noetic keeps ROS under /opt/ros/noetic: the message packages
in its share/, genmsg and rospkg in its lib/python3/dist-packages, all of it
reachable only once its setup.sh is sourced. Here a prefix laid out that way
holds a std_msgs that differs from Debian's (an extra NoeticOnly.msg, a
comment in Header.msg), and the Python modules ROS provides. colcon-mros is
pip-installed, as a wheel with plain pip flags, into a venv that has no
system site packages, so nothing of Debian's Python is seen before sourcing.
"""

import os
import shutil
import subprocess
import sys

import pytest

from support.checkout import TEST_WS
from testing.ros_paths import ros1_package_dir
from support.user_install import copy_sources

pytestmark = pytest.mark.slow

# What a sourced Noetic puts on PYTHONPATH that genmros uses (from Debian here).
ROS_PYTHON_MODULES = ('genmsg', 'em.py', 'rospkg', 'catkin_pkg', 'pyparsing', 'yaml', 'dateutil',
                      'docutils', 'six.py')
DIST_PACKAGES = '/usr/lib/python3/dist-packages'
PREFIX_COMMENT = '# std_msgs/Header of the simulated Noetic prefix\n'

SETUP_SH = '''\
# What /opt/ros/noetic/setup.sh sets, for this prefix.
export ROS_DISTRO=noetic
export ROS_ROOT={prefix}/share/ros
export ROS_PACKAGE_PATH={prefix}/share
export CMAKE_PREFIX_PATH={prefix}
export PYTHONPATH={prefix}/lib/python3/dist-packages
'''


class Noetic:
    def __init__(self, root):
        self.prefix = os.path.join(root, 'opt', 'ros', 'noetic')
        self.venv = os.path.join(root, 'venv')
        self.genmros = os.path.join(self.venv, 'bin', 'genmros')

    def run(self, command, cwd, sourced=True):
        """command in a shell with only the venv on PATH, this prefix sourced or not."""
        environment = {'HOME': os.environ.get('HOME', '/root'),
                       'PATH': os.path.join(self.venv, 'bin') + ':/usr/bin:/bin'}
        if sourced:
            command = '. %s/setup.sh && %s' % (self.prefix, command)
        return subprocess.run(['/bin/sh', '-c', command], cwd=cwd, env=environment,
                              capture_output=True, text=True)


def _make_prefix(prefix):
    share = os.path.join(prefix, 'share')
    for package in ('std_msgs', 'geometry_msgs'):
        shutil.copytree(os.path.dirname(ros1_package_dir(package)), os.path.join(share, package))
    os.makedirs(os.path.join(share, 'ros'))
    with open(os.path.join(share, 'std_msgs', 'msg', 'NoeticOnly.msg'), 'w') as stream:
        stream.write('Header header\nstring distro\n')
    header = os.path.join(share, 'std_msgs', 'msg', 'Header.msg')
    with open(header) as stream:
        text = stream.read()
    os.remove(header)  # a copy of Debian's file, not a link to it
    with open(header, 'w') as stream:
        stream.write(PREFIX_COMMENT + text)
    modules = os.path.join(prefix, 'lib', 'python3', 'dist-packages')
    os.makedirs(modules)
    for module in ROS_PYTHON_MODULES:
        if os.path.exists(os.path.join(DIST_PACKAGES, module)):
            os.symlink(os.path.join(DIST_PACKAGES, module), os.path.join(modules, module))
    with open(os.path.join(prefix, 'setup.sh'), 'w') as stream:
        stream.write(SETUP_SH.format(prefix=prefix))


@pytest.fixture(scope='module')
def noetic(tmp_path_factory):
    root = str(tmp_path_factory.mktemp('noetic'))
    layout = Noetic(root)
    _make_prefix(layout.prefix)
    # A wheel from a copy of the sources (the tree stays clean), installed
    # into a venv without system site packages, with no Debian-only flag.
    source = copy_sources(root)
    wheels = os.path.join(root, 'wheels')
    subprocess.run([sys.executable, '-m', 'pip', 'wheel', '--quiet', '--no-deps',
                    '--no-build-isolation', '-w', wheels, source],
                   check=True, capture_output=True)
    subprocess.run([sys.executable, '-m', 'venv', layout.venv], check=True)
    wheel = os.path.join(wheels, os.listdir(wheels)[0])
    subprocess.run([os.path.join(layout.venv, 'bin', 'pip'), 'install', '--quiet', '--no-deps',
                    wheel], check=True, capture_output=True)
    return layout


def test_before_sourcing_genmros_says_to_source_and_writes_nothing(noetic, tmp_path):
    result = noetic.run('genmros mros-v1-export --type std_msgs/NoeticOnly -o out',
                        str(tmp_path), sourced=False)
    assert result.returncode == 1
    assert result.stderr == (
        'genmros: error: %s cannot import genmsg; install or source genmsg '
        '(Debian: apt-get install python3-genmsg; ROS Noetic: source '
        '/opt/ros/noetic/setup.bash), or run genmros with the Python that has it\n'
        % os.path.join(noetic.venv, 'bin', 'python3'))
    assert os.listdir(str(tmp_path)) == []
    assert noetic.run('genmros --help', str(tmp_path), sourced=False).returncode == 0


def test_sourced_genmros_takes_the_packages_of_the_sourced_prefix(noetic, tmp_path):
    result = noetic.run('genmros mros-v1-export --type std_msgs/NoeticOnly '
                        '--type geometry_msgs/PoseStamped -o out', str(tmp_path))
    assert result.returncode == 0, result.stderr
    out = tmp_path / 'out'
    assert (out / 'std_msgs' / 'NoeticOnly.h').is_file()
    assert PREFIX_COMMENT.strip() in (out / 'std_msgs' / 'Header.h').read_text()
    assert (out / 'geometry_msgs' / 'Point.h').is_file()


def test_sourced_genmros_exports_a_workspace_against_the_prefix(noetic, tmp_path):
    result = noetic.run('genmros mros-v1-export --workspace %s -o out' % TEST_WS, str(tmp_path))
    assert result.returncode == 0, result.stderr
    header = (tmp_path / 'out' / 'std_msgs' / 'Header.h').read_text()
    assert PREFIX_COMMENT.strip() in header


def test_installed_files_are_found_in_the_venv(noetic, tmp_path):
    for command, expected in (('genmros cmake-dir', os.path.join('share', 'genmros', 'cmake')),
                              ('genmros make-fragment', os.path.join('share', 'genmros', 'cmake',
                                                                     'genmros.mk'))):
        result = noetic.run(command, str(tmp_path))
        assert result.returncode == 0, result.stderr
        path = result.stdout.strip()
        assert path == os.path.join(noetic.venv, expected) and os.path.exists(path)


def test_pip_uninstall_leaves_nothing_in_the_venv(noetic, tmp_path):
    result = noetic.run('pip uninstall --yes --quiet colcon-mros', str(tmp_path))
    assert result.returncode == 0, result.stderr
    assert not os.path.exists(noetic.genmros)
    assert not os.path.exists(os.path.join(noetic.venv, 'share', 'genmros'))
