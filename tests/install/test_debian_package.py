# SPDX-License-Identifier: BSD-3-Clause
"""The Debian package as scripts/setup.sh builds it: debian/ (debhelper,
pybuild) through dpkg-buildpackage -b, checked by lintian; what apt
installs with it, Recommends and without. (Its version is Python's:
test_version.py.)"""

import subprocess

import pytest

from colcon_mros import __version__
from support.checkout import REPO

pytestmark = pytest.mark.slow

# The PC targets' packages (iproute2: mros2-pc's network) and mros2's: Recommends, not Depends.
RECOMMENDED = {'g++-arm-linux-gnueabihf', 'qemu-user', 'python3-rosidl', 'iproute2'}
# What generating headers needs.
NEEDED = {'python3-genmsg', 'python3-empy', 'python3-rospkg', 'python3-catkin-pkg',
          'python3-colcon-core', 'patch'}


@pytest.fixture(scope='module')
def deb(tmp_path_factory):
    """The .deb dpkg-buildpackage builds from a copy of the checkout."""
    root = tmp_path_factory.mktemp('deb')
    source = root / 'colcon-mros'
    tar = subprocess.Popen(['tar', '-C', REPO, '--exclude=.git', '--exclude=build',
                            '--exclude=*.egg-info', '-cf', '-', '.'], stdout=subprocess.PIPE)
    subprocess.run(['tar', '-C', str(source.parent), '--one-top-level=colcon-mros', '-xf', '-'],
                   stdin=tar.stdout, check=True)
    assert tar.wait() == 0
    build = subprocess.run(['dpkg-buildpackage', '-b', '-us', '-uc'], cwd=str(source),
                           stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    assert build.returncode == 0, build.stdout[-4000:]
    return str(root / ('colcon-mros_%s_all.deb' % __version__))


def test_lintian_finds_no_error(deb):
    result = subprocess.run(['lintian', deb], capture_output=True, text=True)
    errors = [line for line in result.stdout.splitlines() if line.startswith('E:')]
    assert errors == [], result.stdout


def _field(deb, name):
    return subprocess.run(['dpkg-deb', '-f', deb, name], capture_output=True, text=True,
                          check=True).stdout


def _names(field):
    return {item.split()[0] for item in field.replace('\n', ' ').split(',') if item.strip()}


def test_depends_is_what_headers_need_and_recommends_the_pc_target_and_mros2(deb):
    assert _field(deb, 'Version').strip() == __version__
    depends, recommends = _names(_field(deb, 'Depends')), _names(_field(deb, 'Recommends'))
    assert NEEDED <= depends and not RECOMMENDED & depends
    assert RECOMMENDED <= recommends


def _would_install(deb, tmp_path, *options):
    """The packages apt would install with deb on a machine with nothing
    installed (an empty dpkg status: no package is there yet)."""
    status = tmp_path / 'status'
    status.write_text('')
    result = subprocess.run(['apt-get', 'install', '--simulate', '-o',
                             'Dir::State::status=%s' % status] + list(options) + [deb],
                            capture_output=True, text=True)
    assert result.returncode == 0, result.stdout + result.stderr
    return {line.split()[1] for line in result.stdout.splitlines() if line.startswith('Inst ')}


def test_apt_installs_the_recommends_and_a_headers_only_install_does_without(deb, tmp_path):
    full = _would_install(deb, tmp_path)
    assert {'colcon-mros'} | NEEDED | RECOMMENDED <= full
    headers_only = _would_install(deb, tmp_path, '--no-install-recommends')
    assert {'colcon-mros'} | NEEDED <= headers_only
    assert not RECOMMENDED & headers_only
    # No cross compiler and no emulator of any kind comes with it.
    assert not [name for name in headers_only if name.startswith(('qemu', 'gcc-arm', 'g++-arm'))]
