# SPDX-License-Identifier: BSD-3-Clause
"""What the PC targets of both mROS lines share: the tools that build and
run a program for ``--target arm`` (32-bit ARM Linux under qemu-arm) or
``native``, the sanitizers of ``--sanitize``, and the patched copy of the
user's library that ``--hardened`` builds."""

import filecmp
import os
import shutil
import tempfile

from colcon_mros.core.output import write_files
from colcon_mros.errors import GenmrosError
from colcon_mros.library_tools.patch_series import apply_patches

# The cross compiler of the arm target and what runs its programs.
ARM_COMPILER = 'arm-linux-gnueabihf-g++'
ARM_RUNNER = 'qemu-arm'
# What --sanitize adds to every compile and the link (native target only).
SANITIZER_FLAGS = '-fsanitize=address,undefined -fno-omit-frame-pointer'
# The file in a build directory naming the flags its objects were compiled with.
FLAGS_STAMP = 'compile-flags'


def check_tools(target, sanitize):
    """A GenmrosError naming what to install (or change) if this PC cannot
    build for target."""
    if sanitize and target != 'native':
        raise GenmrosError('--sanitize needs --target native (qemu-arm runs no sanitizer)')
    compiler = ARM_COMPILER if target == 'arm' else 'g++'
    if shutil.which(compiler) is None:
        raise GenmrosError('%s not found: install %s' % (
            compiler, 'g++-arm-linux-gnueabihf (or use --target native)'
            if target == 'arm' else 'g++'))
    if target == 'arm' and shutil.which(ARM_RUNNER) is None:
        raise GenmrosError('%s not found: install qemu-user (or use --target native)'
                           % ARM_RUNNER)
    if shutil.which('make') is None:
        raise GenmrosError('make not found: install make')


def flags_stamp(build_dir, flags):
    """build_dir's FLAGS_STAMP, holding flags ({make variable: value}), rewritten only when
    they differ from the last build's. The objects depend on it, so that a build with other
    flags (a target, --sanitize, -D) compiles them again: make compares times, not flags."""
    write_files(build_dir, {FLAGS_STAMP: ''.join('%s=%s\n' % item
                                                 for item in sorted(flags.items()))})
    return os.path.join(build_dir, FLAGS_STAMP)


def runner(target):
    """The command that runs a program built for target on this PC."""
    return [ARM_RUNNER] if target == 'arm' else []


def patched_copy(root, paths, patches, destination):
    """destination, holding paths of root (directories and files, relative) with
    patches applied; a file whose text is the same as at the last build
    keeps its time, so that make rebuilds only what changed."""
    os.makedirs(os.path.dirname(os.path.abspath(destination)), exist_ok=True)
    with tempfile.TemporaryDirectory(prefix='genmros-patched-',
                                     dir=os.path.dirname(os.path.abspath(destination))) as scratch:
        for path in paths:
            if os.path.isdir(os.path.join(root, path)):
                shutil.copytree(os.path.join(root, path), os.path.join(scratch, path),
                                symlinks=True)
            else:
                shutil.copy2(os.path.join(root, path), os.path.join(scratch, path))
        apply_patches(scratch, patches)
        for directory, _, names in os.walk(scratch):
            target = os.path.join(destination, os.path.relpath(directory, scratch))
            os.makedirs(target, exist_ok=True)
            for name in names:
                source, copy = os.path.join(directory, name), os.path.join(target, name)
                if not os.path.isfile(copy) or not filecmp.cmp(source, copy, shallow=False):
                    shutil.copy2(source, copy)
    return destination
