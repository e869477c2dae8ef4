"""Installing and uninstalling colcon-mros (issue 8): after
scripts/uninstall.sh nothing of genmros is left where catkin looks, and an
ordinary message workspace still builds with catkin_make and colcon;
scripts/setup.sh puts it back and leaves the source tree as it was. The
install is restored even when a check fails."""

import os
import shutil
import subprocess

from conftest import REPO, TEST_WS

MARKER = '/etc/ros/genmsg/genmros'


def _run(argv, cwd, **kwargs):
    result = subprocess.run(argv, cwd=cwd, capture_output=True, text=True, **kwargs)
    assert result.returncode == 0, ' '.join(argv) + '\n' + (result.stdout + result.stderr)[-4000:]
    return result


def _ignored_files():
    return _run(['git', 'status', '--porcelain', '--ignored', '--untracked-files=all'], REPO).stdout


def _ordinary_workspace(root):
    source = root / 'src'
    shutil.copytree(os.path.join(TEST_WS, 'src', 'mros_test_base'), str(source / 'mros_test_base'))
    return str(root)


def test_uninstall_leaves_catkin_and_colcon_working_and_setup_reinstalls(tmp_path):
    environment = dict(os.environ, PATH='/usr/bin:/bin:/usr/sbin:/sbin')
    before = _ignored_files()
    try:
        _run([os.path.join(REPO, 'scripts', 'uninstall.sh')], REPO)
        assert not os.path.lexists(MARKER)
        assert shutil.which('genmros', path=environment['PATH']) is None
        assert subprocess.run(['/usr/bin/python3', '-m', 'pip', 'show', 'colcon-mros'],
                              capture_output=True).returncode != 0

        catkin = _ordinary_workspace(tmp_path / 'catkin_ws')
        _run(['catkin_make', '-C', catkin], catkin, env=environment)
        assert os.path.isfile(os.path.join(catkin, 'devel', 'include', 'mros_test_base', 'Vector3i.h'))
        assert not os.path.exists(os.path.join(catkin, 'devel', 'share', 'genmros'))

        colcon = _ordinary_workspace(tmp_path / 'colcon_ws')
        _run(['colcon', 'build'], colcon, env=environment)
        assert os.path.isfile(os.path.join(colcon, 'install', 'mros_test_base', 'include', 'mros_test_base',
                                           'Vector3i.h'))
    finally:
        _run([os.path.join(REPO, 'scripts', 'setup.sh')], REPO)
    assert os.path.islink(MARKER) and os.path.isfile(os.path.realpath(MARKER))
    assert shutil.which('genmros', path=environment['PATH'] + ':/usr/local/bin')
    assert _ignored_files() == before  # no build/ or *.egg-info in the source tree
