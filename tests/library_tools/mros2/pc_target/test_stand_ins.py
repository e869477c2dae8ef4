# SPDX-License-Identifier: BSD-3-Clause
"""The mros2 PC target's stand-ins: warning-free for the host and the arm target, and
defining exactly the symbols docs/mros2.md lists (test_mros2_pc.py shows, with a checkout,
that mros2's link needs each of them)."""

import glob
import os
import re
import shutil
import subprocess

import pytest

from colcon_mros.library_tools.mros2.pc_target.build import TARGET_DIR, settings_header
from colcon_mros.library_tools.pc_build import ARM_COMPILER
from support.checkout import REPO
from testing import mros2_pc

SOURCES = sorted(glob.glob(os.path.join(TARGET_DIR, 'src', '*.cpp')))
DOCS = os.path.join(REPO, 'docs', 'mros2.md')
FLAGS = ['-std=gnu++14', '-O2', '-Wall', '-Wextra', '-pedantic', '-Werror', '-pthread']


def compile_stand_ins(compiler, out_dir, extra=()):
    """The stand-ins' objects, compiled by compiler with a settings header as genmros
    writes it."""
    settings = os.path.join(out_dir, 'settings')
    os.makedirs(settings)
    with open(os.path.join(settings, 'mros2_pc_settings.h'), 'w') as stream:
        stream.write(settings_header('192.168.11.3', 4096, 1024,
                                     [('ReaderThread', 'rtps::Config::X, "config.h":1')], 0))
    objects = []
    for source in SOURCES:
        obj = os.path.join(out_dir, os.path.basename(source) + '.o')
        result = subprocess.run([compiler] + FLAGS + list(extra) + [
            '-I', settings, '-I', os.path.join(TARGET_DIR, 'include'), '-c', source, '-o', obj],
            capture_output=True, text=True)
        assert result.returncode == 0 and result.stderr == '', result.stderr
        objects.append(obj)
    return objects


def documented_symbols():
    with open(DOCS) as stream:
        text = stream.read()
    table = text[text.index('### What stands in for the board'):text.index('**The board')]
    return {name for row in table.splitlines() if row.startswith('| ') and '`' in row
            for name in re.findall(r'`(\w+)`', row.split('|')[2])}


def test_native_objects_define_the_documented_symbols(tmp_path):
    objects = compile_stand_ins('g++', str(tmp_path))
    assert mros2_pc.defined_c_symbols(objects) == documented_symbols()


@pytest.mark.slow
@pytest.mark.skipif(shutil.which(ARM_COMPILER) is None, reason='needs %s' % ARM_COMPILER)
def test_arm_objects_warning_free(tmp_path):
    objects = compile_stand_ins(ARM_COMPILER, str(tmp_path),
                                ['-mthumb', '-mcpu=cortex-a7', '-mfpu=vfpv4-d16',
                                 '-mfloat-abi=hard'])
    assert mros2_pc.defined_c_symbols(objects, 'arm-linux-gnueabihf-nm') == documented_symbols()
