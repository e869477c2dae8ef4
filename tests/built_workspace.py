"""test_ws built with catkin_make once per process, in a temporary directory:
the real roscpp/rospy nodes of mros_test_nodes, with gencpp, genpy and
genmros messages (the genmros ones also exported to mros_export/), for the
tests and the evaluation that run the mROS v1 library against ROS nodes."""

import atexit
import functools
import os
import shutil
import subprocess
import tempfile

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
TEST_WS = os.path.join(REPO, 'test_ws')
PYTHON = '/usr/bin/python3'  # the interpreter that has genmsg, catkin_pkg, rospy


def scratch(prefix):
    """A temporary directory removed when the process exits."""
    path = tempfile.mkdtemp(prefix=prefix)
    atexit.register(shutil.rmtree, path, True)
    return path


def _run(argv, log_path, **kwargs):
    with open(log_path, 'w') as log:
        result = subprocess.run(argv, stdout=log, stderr=subprocess.STDOUT, **kwargs)
    if result.returncode != 0:
        with open(log_path) as log:
            raise RuntimeError('%s failed:\n%s' % (' '.join(argv), log.read()[-6000:]))


class Workspace:
    """A built copy of test_ws."""

    def __init__(self, root):
        self.root = root
        self.setup_bash = os.path.join(root, 'devel', 'setup.bash')
        self.mros_export = os.path.join(root, 'mros_export')
        self.lib = os.path.join(root, 'devel', 'lib', 'mros_test_nodes')
        self.scripts = os.path.join(root, 'src', 'mros_test_nodes', 'scripts')

    def roscpp(self, node, *arguments):
        return [os.path.join(self.lib, node)] + list(arguments)

    def rospy(self, script, *arguments):
        return [PYTHON, os.path.join(self.scripts, script)] + list(arguments)


@functools.lru_cache(maxsize=None)
def workspace(root=None):
    root = root or scratch('mros_test_ws_')
    shutil.copytree(os.path.join(TEST_WS, 'src'), os.path.join(root, 'src'), dirs_exist_ok=True)
    built = Workspace(root)
    _run(['catkin_make', '-C', root, '-DPYTHON_EXECUTABLE=' + PYTHON, '-DCMAKE_BUILD_TYPE=Release',
          '-DMROS_EXPORT_DIR=' + built.mros_export, '-j2'],
         os.path.join(root, 'catkin_make.log'), cwd=root)
    return built
