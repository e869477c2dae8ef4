# SPDX-License-Identifier: BSD-3-Clause
"""What genmros' generator mode leaves in an export dir (export_claims): the
files of types no definition contains any more go, files genmros did not
write stay, and `genmros mros-v1-prune-export` does the same after catkin drops a
definition's claim. The catkin side is in test_catkin_incremental.py."""

import os

from colcon_mros.mros_v1.cpp import SUPPORT_HEADERS
from support.checkout import run_genmros
from testing.ros_paths import ros1_package_dir

STD_MSGS = ros1_package_dir('std_msgs')


def _generate(tmp_path, name, text):
    source = tmp_path / 'src' / 'demo' / 'msg'
    source.mkdir(parents=True, exist_ok=True)
    (source / name).write_text(text)
    run_genmros('generate', str(source / name), '-p', 'demo',
                '-o', str(tmp_path / 'devel' / 'demo'),
                '-I', 'demo:%s' % source, '-I', 'std_msgs:%s' % STD_MSGS,
                '--add-to-export-dir', str(tmp_path / 'export'))


def _exported(tmp_path):
    root = tmp_path / 'export'
    return {str(path.relative_to(root)) for path in root.rglob('*')
            if path.is_file() and '.genmros' not in path.parts}


def test_a_type_no_longer_contained_leaves_and_foreign_files_stay(tmp_path):
    _generate(tmp_path, 'Lamp.msg', 'std_msgs/ColorRGBA color\n')
    _generate(tmp_path, 'Stamp.msg', 'Header header\n')
    foreign = tmp_path / 'export' / 'include' / 'std_msgs' / 'Notes.h'
    foreign.write_text('// written by hand\n')
    assert 'include/std_msgs/ColorRGBA.h' in _exported(tmp_path)

    _generate(tmp_path, 'Lamp.msg', 'uint32 color\n')
    exported = _exported(tmp_path)
    assert 'include/std_msgs/ColorRGBA.h' not in exported
    assert 'share/std_msgs/msg/ColorRGBA.msg' not in exported
    assert {'include/std_msgs/Header.h', 'share/std_msgs/msg/Header.msg',
            'include/demo/Lamp.h'} | {'include/' + name for name in SUPPORT_HEADERS} <= exported
    assert foreign.read_text() == '// written by hand\n'


def test_prune_export_removes_what_only_a_dropped_claim_named(tmp_path):
    _generate(tmp_path, 'Lamp.msg', 'std_msgs/ColorRGBA color\n')
    _generate(tmp_path, 'Stamp.msg', 'Header header\n')
    # What catkin does when Stamp.msg leaves its package.
    os.remove(tmp_path / 'export' / '.genmros' / 'claims' / 'demo' / 'msg' / 'Stamp.msg')
    result = run_genmros('mros-v1-prune-export', str(tmp_path / 'export'))
    removed = {line.split('genmros: removed ')[1] for line in result.stdout.splitlines()}
    assert removed == {str(tmp_path / 'export' / relative) for relative in (
        'include/demo/Stamp.h', 'share/demo/msg/Stamp.msg',
        'include/std_msgs/Header.h', 'share/std_msgs/msg/Header.msg')}
    exported = _exported(tmp_path)
    assert {'include/demo/Lamp.h', 'include/std_msgs/ColorRGBA.h',
            'share/std_msgs/package.xml'} <= exported
    assert not os.path.exists(tmp_path / 'export' / 'include' / 'std_msgs' / 'Header.h')
    assert run_genmros('mros-v1-prune-export', str(tmp_path / 'export')).stdout == ''


def test_prune_export_of_a_missing_dir_is_one_line(tmp_path):
    result = run_genmros('mros-v1-prune-export', str(tmp_path / 'nowhere'), check=False)
    assert result.returncode == 1
    assert result.stderr == 'genmros: error: %s: export dir is not a directory\n' % (
        tmp_path / 'nowhere')
    assert not os.path.exists(tmp_path / 'nowhere')
