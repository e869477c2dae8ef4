# SPDX-License-Identifier: BSD-3-Clause
"""The Debian packages as scripts/setup.sh builds them: debian/ (debhelper,
pybuild) through dpkg-buildpackage -b, checked by lintian: python3-colcon-mros,
named as Debian names Python packages, and colcon-mros, the transitional
package of its old name; what apt installs with python3-colcon-mros,
Recommends and without, and how it replaces an installed colcon-mros. (Their
version is Python's: test_version.py. That scripts/uninstall.sh purges both:
test_install.py.)"""

import subprocess

import pytest

from colcon_mros import __version__
from support.checkout import REPO

pytestmark = pytest.mark.slow

PACKAGE = 'python3-colcon-mros'
# The package's name until 0.1.0, kept for one release as a transitional package.
TRANSITIONAL = 'colcon-mros'
RENAMED_IN = '0.1.1'

# The PC targets' packages (iproute2: mros2-pc's network) and mros2's: Recommends, not Depends.
RECOMMENDED = {'g++-arm-linux-gnueabihf', 'qemu-user', 'python3-rosidl', 'iproute2'}
# What generating headers needs.
NEEDED = {'python3-genmsg', 'python3-empy', 'python3-rospkg', 'python3-catkin-pkg',
          'python3-colcon-core', 'patch'}


@pytest.fixture(scope='module')
def debs(tmp_path_factory):
    """The .debs dpkg-buildpackage builds from a copy of the checkout, by package."""
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
    built = {path.name.split('_')[0]: str(path) for path in root.glob('*.deb')}
    assert built == {package: str(root / ('%s_%s_all.deb' % (package, __version__)))
                     for package in (PACKAGE, TRANSITIONAL)}
    return built


@pytest.fixture(scope='module')
def deb(debs):
    return debs[PACKAGE]


def test_lintian_finds_no_error(debs):
    result = subprocess.run(['lintian'] + sorted(debs.values()), capture_output=True, text=True)
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


def _apt_simulation(debs, tmp_path, *options, status=''):
    """What apt would do to install debs on a machine whose dpkg status is
    status (empty: no package is there yet): its Inst, Remv and Conf lines."""
    status_file = tmp_path / 'status'
    status_file.write_text(status)
    result = subprocess.run(['apt-get', 'install', '--simulate', '-o',
                             'Dir::State::status=%s' % status_file] + list(options) + list(debs),
                            capture_output=True, text=True)
    assert result.returncode == 0, result.stdout + result.stderr
    return [line for line in result.stdout.splitlines() if line.startswith(('Inst ', 'Remv '))]


def _would_install(deb, tmp_path, *options):
    """The packages apt would install with deb on a machine with nothing installed."""
    return {line.split()[1] for line in _apt_simulation([deb], tmp_path, *options)}


def test_apt_installs_the_recommends_and_a_headers_only_install_does_without(deb, tmp_path):
    full = _would_install(deb, tmp_path)
    assert {PACKAGE} | NEEDED | RECOMMENDED <= full
    headers_only = _would_install(deb, tmp_path, '--no-install-recommends')
    assert {PACKAGE} | NEEDED <= headers_only
    assert not RECOMMENDED & headers_only
    # No cross compiler and no emulator of any kind comes with it, nor the old name.
    assert not [name for name in headers_only if name.startswith(('qemu', 'gcc-arm', 'g++-arm'))]
    assert TRANSITIONAL not in full


def test_the_transitional_package_only_depends_on_the_renamed_one(debs):
    transitional = debs[TRANSITIONAL]
    assert _field(transitional, 'Depends').strip() == '%s (= %s)' % (PACKAGE, __version__)
    assert _field(transitional, 'Section').strip() == 'oldlibs'
    assert _field(transitional, 'Priority').strip() == 'optional'
    assert 'transitional package' in _field(transitional, 'Description')
    contents = subprocess.run(['dpkg-deb', '--contents', transitional], capture_output=True,
                              text=True, check=True).stdout
    assert [line.split()[-1] for line in contents.splitlines() if not line.startswith('d')] == [
        './usr/share/doc/colcon-mros/changelog.gz', './usr/share/doc/colcon-mros/copyright']


def test_the_renamed_package_takes_over_from_an_installed_colcon_mros(debs, tmp_path):
    # Every file of colcon-mros 0.1.0 is python3-colcon-mros' now, /etc/ros/genmsg/genmros too.
    for field in ('Breaks', 'Replaces'):
        assert _field(debs[PACKAGE], field).strip() == '%s (<< %s~)' % (TRANSITIONAL, RENAMED_IN)
    installed = ('Package: colcon-mros\nStatus: install ok installed\nArchitecture: all\n'
                 'Version: 0.1.0\nMaintainer: colcon-mros developers <dev@colcon-mros.invalid>\n'
                 'Description: mROS message headers\n')
    # Alone (scripts/setup.sh), it removes colcon-mros; with the transitional
    # package (an upgrade from a repository), colcon-mros is upgraded to it.
    alone = _apt_simulation([debs[PACKAGE]], tmp_path, status=installed)
    assert 'Remv colcon-mros [0.1.0]' in alone
    upgrade = _apt_simulation([debs[PACKAGE], debs[TRANSITIONAL]], tmp_path, status=installed)
    assert not [line for line in upgrade if line.startswith('Remv ')]
    assert {line.split(' (')[0] for line in upgrade if 'colcon-mros' in line.split()[1]} == {
        'Inst colcon-mros [0.1.0]', 'Inst python3-colcon-mros'}
