# SPDX-License-Identifier: BSD-3-Clause
"""Installing and uninstalling colcon-mros: scripts/setup.sh
installs it as the Debian package python3-colcon-mros, so dpkg owns every
file of it, the catkin generator marker included; after scripts/uninstall.sh
nothing of genmros is left, neither package (nor colcon-mros, the old name)
is known to dpkg, and an ordinary message workspace still builds with
catkin_make and colcon; scripts/setup.sh puts it back and leaves the source
tree as it was. The install is restored even when a check fails."""

import os
import shutil
import subprocess

from support.checkout import REPO, TEST_WS
from support.user_install import NOBODY, install_as_nobody, pip_flags

import pytest

pytestmark = pytest.mark.slow

MARKER = '/etc/ros/genmsg/genmros'
PACKAGE = 'python3-colcon-mros'
# The package's name until 0.1.0, now its transitional package.
OLD_NAME = 'colcon-mros'


def _run(argv, cwd, **kwargs):
    result = subprocess.run(argv, cwd=cwd, capture_output=True, text=True, **kwargs)
    assert result.returncode == 0, ' '.join(argv) + '\n' + (result.stdout + result.stderr)[-4000:]
    return result


def _ignored_files():
    return _run(['git', 'status', '--porcelain', '--ignored', '--untracked-files=all'],
                REPO).stdout


def _package_files():
    """The files dpkg lists for python3-colcon-mros."""
    return _run(['dpkg', '-L', PACKAGE], REPO).stdout.split()


def _dpkg_knows(package):
    """Whether dpkg has package installed, or its configuration files left."""
    result = subprocess.run(['dpkg-query', '-W', '-f=${Status}', package],
                            capture_output=True, text=True)
    return result.returncode == 0 and not result.stdout.endswith('not-installed')


def _ordinary_workspace(root):
    source = root / 'src'
    shutil.copytree(os.path.join(TEST_WS, 'src', 'mros_test_base'), str(source / 'mros_test_base'))
    return str(root)


def test_uninstall_leaves_catkin_and_colcon_working_and_setup_reinstalls(tmp_path):
    environment = dict(os.environ, PATH='/usr/bin:/bin:/usr/sbin:/sbin')
    before = _ignored_files()
    try:
        installed = _package_files()
        _run([os.path.join(REPO, 'scripts', 'uninstall.sh')], REPO)
        assert not _dpkg_knows(PACKAGE) and not _dpkg_knows(OLD_NAME)
        assert not os.path.lexists(MARKER)
        assert shutil.which('genmros', path=environment['PATH']) is None
        assert subprocess.run(['/usr/bin/python3', '-m', 'pip', 'show', 'colcon-mros'],
                              capture_output=True).returncode != 0
        left = [path for path in installed if os.path.lexists(path) and not os.path.isdir(path)]
        assert left == []
        for directory in ('/usr/share/genmros', '/usr/lib/python3/dist-packages/colcon_mros'):
            assert not os.path.exists(directory)  # __pycache__ included

        catkin = _ordinary_workspace(tmp_path / 'catkin_ws')
        _run(['catkin_make', '-C', catkin], catkin, env=environment)
        assert os.path.isfile(os.path.join(catkin, 'devel', 'include',
                              'mros_test_base', 'Vector3i.h'))
        assert not os.path.exists(os.path.join(catkin, 'devel', 'share', 'genmros'))

        colcon = _ordinary_workspace(tmp_path / 'colcon_ws')
        _run(['colcon', 'build'], colcon, env=environment)
        assert os.path.isfile(os.path.join(colcon, 'install', 'mros_test_base', 'include',
                                           'mros_test_base', 'Vector3i.h'))
    finally:
        _run([os.path.join(REPO, 'scripts', 'setup.sh')], REPO)
    assert _run(['dpkg', '-S', MARKER], REPO).stdout == '%s: %s\n' % (PACKAGE, MARKER)
    assert _run(['dpkg', '-S', shutil.which('genmros', path=environment['PATH'])],
                REPO).stdout.startswith(PACKAGE + ': ')
    # The transitional package is for upgrades from a repository: setup.sh
    # leaves it out (and purges an earlier setup.sh's colcon-mros).
    assert not _dpkg_knows(OLD_NAME)
    assert _ignored_files() == before  # no build/ or *.egg-info in the source tree


def test_a_user_install_registers_the_generator_through_its_catkin_prefix(tmp_path):
    # No /etc/ros/genmsg/genmros while the Debian package is away: only the
    # prefix `genmros catkin-prefix` prints, on CMAKE_PREFIX_PATH, makes
    # catkin run the user's genmros.
    user = install_as_nobody()
    try:
        _run([os.path.join(REPO, 'scripts', 'uninstall.sh')], REPO)
        prefix = user.run(['genmros', 'catkin-prefix'], user.root).stdout.strip()
        assert prefix == os.path.join(user.prefix, 'share', 'genmros', 'catkin_prefix')
        header = os.path.join('devel', 'share', 'genmros', 'include',
                              'mros_test_base', 'Vector3i.h')
        # docs/install.md's line, run where ~/.local/bin is not on PATH yet.
        registration = _docs_catkin_prefix_line()
        for registered in (True, False):
            workspace = os.path.join(user.root, 'ws_%s' % registered)
            shutil.copytree(os.path.join(TEST_WS, 'src', 'mros_test_base'),
                            os.path.join(workspace, 'src', 'mros_test_base'))
            subprocess.run(['chown', '-R', '%d:%d' % (NOBODY, NOBODY), workspace], check=True)
            script = '%s && catkin_make' % registration if registered else 'catkin_make'
            log = user.run(['bash', '-c', script], workspace, bin_on_path=False).stdout
            assert os.path.isfile(os.path.join(workspace, header)) == registered, log[-2000:]
        user.run(['/usr/bin/python3', '-m', 'pip', 'uninstall', '--yes', '--quiet'] +
                 [flag for flag in pip_flags() if flag == '--break-system-packages'] +
                 ['colcon-mros'], user.root)
        assert not os.path.exists(prefix)
        # Without the install the line fails, saying why, and sets nothing.
        result = user.run(['bash', '-c', registration + ' && echo "set: $CMAKE_PREFIX_PATH"'],
                          user.root, check=False, bin_on_path=False)
        assert result.returncode != 0 and 'set:' not in result.stdout
        assert 'No module named colcon_mros' in result.stderr
    finally:
        _run([os.path.join(REPO, 'scripts', 'setup.sh')], REPO)
        shutil.rmtree(user.root)


def _docs_catkin_prefix_line():
    """docs/install.md's command that puts an install's catkin prefix on CMAKE_PREFIX_PATH."""
    with open(os.path.join(REPO, 'docs', 'install.md')) as readme:
        lines = [line.split('#')[0].strip() for line in readme
                 if 'catkin-prefix' in line and line.lstrip().startswith('prefix=')]
    assert len(set(lines)) == 1, lines
    return lines[0]


def test_nothing_test_only_is_installed():
    # What the tests, the benches and the main job share stays in the
    # repository (testing/); the package has the product alone.
    python_files = [path for path in _package_files() if path.endswith('.py')]
    assert any(path.endswith('/colcon_mros/cli.py') for path in python_files)
    repository_only = [path for path in python_files
                       if not path.startswith('/usr/lib/python3/dist-packages/colcon_mros/')]
    assert repository_only == []
    assert not any(os.path.basename(path) in ('ros_graph.py', 'tcpros_peer.py')
                   for path in python_files)


def test_the_debian_packages_genmros_finds_its_cmake_and_make_files():
    # pybuild installs the package without an install record: genmros finds
    # share/genmros from where its Python package is (/usr/lib/python3/dist-packages).
    environment = {'PATH': '/usr/bin:/bin', 'HOME': os.environ.get('HOME', '/root')}
    for subcommand, expected in (('cmake-dir', '/usr/share/genmros/cmake'),
                                 ('make-fragment', '/usr/share/genmros/cmake/genmros.mk'),
                                 ('catkin-prefix', '/usr/share/genmros/catkin_prefix')):
        result = _run(['/usr/bin/genmros', subcommand], '/', env=environment)
        assert result.stdout == expected + '\n'
