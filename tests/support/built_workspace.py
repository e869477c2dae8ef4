# SPDX-License-Identifier: BSD-3-Clause
"""test_ws built with catkin_make once per process, in a temporary directory:
the real roscpp/rospy nodes of mros_test_nodes, with gencpp, genpy and
genmros messages (the genmros ones also exported to mros_export/, by this
checkout), for the tests that run the mROS v1 library against ROS nodes."""

import atexit
import functools
import os
import shutil
import tempfile

from support.checkout import TEST_WS
from support.checkout_install import checkout_install
from testing.ros_graph import CatkinWorkspace


def scratch(prefix):
    """A temporary directory removed when the process exits."""
    path = tempfile.mkdtemp(prefix=prefix)
    atexit.register(shutil.rmtree, path, True)
    return path


@functools.lru_cache(maxsize=None)
def workspace(root=None):
    root = root or scratch('mros_test_ws_')
    shutil.copytree(os.path.join(TEST_WS, 'src'), os.path.join(root, 'src'), dirs_exist_ok=True)
    return CatkinWorkspace(root, 'mros_test_nodes').build(
        os.path.join(root, 'catkin_make.log'), '-DCMAKE_BUILD_TYPE=Release', '-j2',
        environment=checkout_install().environment(os.environ))
