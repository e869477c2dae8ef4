# SPDX-License-Identifier: BSD-3-Clause
"""The unit checks of embeddedRTPS' real writers and readers (testing/mros2_library's
stateful_reader_check.cpp, stateful_writer_check.cpp and stateless_writer_check.cpp), built on
a copy of MROS2_ROOT with some of genmros' mros2 patches, and run step by step."""

import os
import shutil
import subprocess

from colcon_mros.library_tools.mros2.patches import LIBRARY_DIRS, mros2_patches
from colcon_mros.library_tools.mros2.pc_target.build import TARGET_DIR
from colcon_mros.library_tools.patch_series import apply_patches
from support.checkout import REPO
from support.user_checkouts import MROS2_ROOT

STAND_IN = os.path.join(REPO, 'testing', 'mros2_library')


def build_check(work, name, config, patches):
    """The check testing/mros2_library/<name>.cpp, compiled in work against MROS2_ROOT with
    the series' patches named in patches and the board config in testing/mros2_library/
    <config>/; its program's path."""
    checkout = work / 'mros2'
    for part in LIBRARY_DIRS:
        shutil.copytree(os.path.join(MROS2_ROOT, part), str(checkout / part))
    apply_patches(str(checkout), [patch for patch in mros2_patches() if patch.name in patches])
    rtps = checkout / 'embeddedRTPS'
    program = str(work / name)
    command = ['g++', '-std=gnu++14', '-g', '-fsanitize=address,undefined',
               '-fno-sanitize-recover=all', '-I', os.path.join(STAND_IN, config),
               '-I', os.path.join(TARGET_DIR, 'include'), '-I', str(rtps / 'include'),
               '-I', str(rtps / 'thirdparty' / 'Micro-CDR' / 'include'),
               str(rtps / 'src' / 'messages' / 'MessageTypes.cpp'),
               str(rtps / 'src' / 'storages' / 'PBufWrapper.cpp'),
               os.path.join(TARGET_DIR, 'src', 'pbuf.cpp'),
               os.path.join(STAND_IN, 'lwip_sys.cpp'), os.path.join(STAND_IN, name + '.cpp'),
               '-pthread', '-o', program]
    result = subprocess.run(command, capture_output=True, text=True)
    assert result.returncode == 0, result.stderr[-4000:]
    return program


# What a patch's check is built on: mros2 as it is, with the patch alone, with the series.
VERSIONS = ['as-it-is', 'patch', 'series']


def build_version(version, patch, work, name, config):
    """The check name built in work on the version (of VERSIONS) with the patch."""
    patches = {'as-it-is': [], 'patch': [patch],
               'series': [each.name for each in mros2_patches()]}[version]
    return build_check(work, name, config, patches)


class RunningCheck:
    """A check running: a step in, the lines it printed out."""

    def __init__(self, program):
        self.process = subprocess.Popen([program], stdin=subprocess.PIPE,
                                        stdout=subprocess.PIPE, text=True)

    def step(self, line):
        """The lines the step printed, up to the check's "done"."""
        self.process.stdin.write(line + '\n')
        self.process.stdin.flush()
        return [output.strip() for output in iter(self.process.stdout.readline, 'done\n')]

    def close(self):
        self.process.stdin.close()
        assert self.process.wait(timeout=60) == 0
