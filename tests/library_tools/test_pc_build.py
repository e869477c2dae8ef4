# SPDX-License-Identifier: BSD-3-Clause
"""What both PC targets share (colcon_mros/library_tools/pc_build.py): the flags stamp that
makes a build with other flags compile its objects again, here through mros2_pc.mk's rule."""

import os
import subprocess

from colcon_mros.library_tools.mros2.pc_target.build import MAKEFILE
from colcon_mros.library_tools.pc_build import FLAGS_STAMP, flags_stamp


def test_the_stamp_is_rewritten_only_when_the_flags_change(tmp_path):
    path = flags_stamp(str(tmp_path), {'TARGET': 'arm', 'SANITIZER_FLAGS': ''})
    assert path == str(tmp_path / FLAGS_STAMP)
    assert open(path).read() == 'SANITIZER_FLAGS=\nTARGET=arm\n'
    before = os.stat(path)
    flags_stamp(str(tmp_path), {'SANITIZER_FLAGS': '', 'TARGET': 'arm'})
    after = os.stat(path)
    assert (after.st_ino, after.st_mtime_ns) == (before.st_ino, before.st_mtime_ns)
    flags_stamp(str(tmp_path), {'TARGET': 'native', 'SANITIZER_FLAGS': '-O0'})
    assert open(path).read() == 'SANITIZER_FLAGS=-O0\nTARGET=native\n'


def test_an_object_is_compiled_again_when_the_flags_change(tmp_path):
    source = tmp_path / 'app.c'
    source.write_text('int app_value(void) { return 1; }\n')
    build = tmp_path / 'build'

    def make(sanitizer_flags, *options):
        stamp = flags_stamp(str(build), {'TARGET': 'native', 'SANITIZER_FLAGS': sanitizer_flags})
        return subprocess.run(['make', '--no-print-directory', '-f', MAKEFILE] + list(options) + [
            'TARGET=native', 'BUILD=%s' % build, 'APP_SOURCES=%s' % source,
            'APP_DIR=%s' % tmp_path, 'CONFIG_DIR=%s' % tmp_path, 'PROGRAM=app',
            'SANITIZER_FLAGS=%s' % sanitizer_flags, 'FLAGS_STAMP=%s' % stamp, 'app'],
            capture_output=True, text=True)

    assert make('').returncode == 0
    assert make('', '-q').returncode == 0  # up to date
    assert make('-DWITH_OTHER_FLAGS', '-q').returncode == 1
    assert make('-DWITH_OTHER_FLAGS').returncode == 0
    assert make('-DWITH_OTHER_FLAGS', '-q').returncode == 0
