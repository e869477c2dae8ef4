# SPDX-License-Identifier: BSD-3-Clause
"""Trees of files for the tests that write definitions and check what a run
left: writing them, snapshotting them (contents and times), a package.xml,
and the one-line error a bad run must give."""

import os


def write_tree(root, files):
    for relative, content in files.items():
        path = os.path.join(root, relative)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, 'wb') as stream:
            stream.write(content if isinstance(content, bytes) else content.encode())


def snapshot(root):
    state = {}
    for directory, _, names in os.walk(root):
        for name in names:
            path = os.path.join(directory, name)
            with open(path, 'rb') as stream:
                state[os.path.relpath(path, root)] = (stream.read(), os.stat(path).st_mtime_ns)
    return state


def assert_one_line_error(result, *fragments):
    assert result.returncode == 1, result.stdout + result.stderr
    lines = result.stderr.strip().split('\n')
    assert len(lines) == 1, result.stderr
    assert lines[0].startswith('genmros: error: ')
    for fragment in fragments:
        assert fragment in lines[0], lines[0]


def package_xml(name):
    return ('<?xml version="1.0"?>\n<package format="2">\n  <name>%s</name>\n'
            '  <version>0.0.1</version>\n'
            '  <description>Hostile definitions.</description>\n'
            '  <maintainer email="dev@colcon-mros.invalid">colcon-mros developers</maintainer>\n'
            '  <license>BSD</license>\n  <buildtool_depend>catkin</buildtool_depend>\n'
            '</package>\n' % name)
