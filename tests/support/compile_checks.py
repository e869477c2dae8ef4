# SPDX-License-Identifier: BSD-3-Clause
"""What the compile tests share: the strict flags, the language modes and
the CPUs of mROS boards every header must compile for, and a translation
unit that instantiates the whole interface of every generated type."""

import glob
import os
import re

import pytest

STRICT_FLAGS = ['-Wall', '-Wextra', '-Wshadow',
                '-pedantic', '-Werror', '-fno-exceptions', '-fno-rtti']
LANGUAGE_MODES = ['gnu++98', 'c++11', 'c++14', 'c++17']
# The CPUs of mROS boards: GR-PEACH's Cortex-A9 (its Makefile's line) and
# two Cortex-M cores.
TARGETS = {
    'host': ['g++'],
    'cortex-m0': ['arm-none-eabi-g++', '-mcpu=cortex-m0', '-mthumb'],
    'cortex-m4': ['arm-none-eabi-g++', '-mcpu=cortex-m4', '-mthumb', '-mfloat-abi=hard',
                  '-mfpu=fpv4-sp-d16'],
    'cortex-a9': ['arm-none-eabi-g++', '-mcpu=cortex-a9', '-marm', '-mfpu=vfpv3',
                  '-mfloat-abi=hard', '-mno-unaligned-access'],
}
# The targets as test parameters: a cross compiler's run is slow.
TARGET_PARAMS = [name if name == 'host' else pytest.param(name, marks=pytest.mark.slow)
                 for name in sorted(TARGETS)]


def every_header_translation_unit(include_root, path):
    """A translation unit that includes every header under include_root and
    instantiates the whole interface of every message type."""
    headers = sorted(os.path.relpath(p, include_root)
                     for p in glob.glob(os.path.join(include_root, '**', '*.h'), recursive=True))
    types = []
    for header in headers:
        with open(os.path.join(include_root, header)) as stream:
            types.extend(re.findall(r'struct Fields<(\S+)>', stream.read()))
    lines = ['#include <%s>' % h for h in headers if h != 'message_class_specialization.h']
    lines += ['',
              'template <class T> int exercise(uint8_t* buffer, uint32_t size) {',
              '  T message;',
              '  char* cursor = reinterpret_cast<char*>(buffer);',
              '  int total = message.dataSize() + message.serialize(buffer, size) +',
              '              message.deserialize(buffer, size);',
              '  message.memCopy(cursor);',
              '  message.deserialize(cursor);',
              '  subtask_methods::CallCallbackFuncs<T::MROS_TYPE_ID>::call(0, cursor, size);',
              '  return total + static_cast<int>(message.serializedLength());',
              '}',
              '',
              'int exerciseAll(uint8_t* buffer, uint32_t size) {',
              '  int total = 0;']
    lines += ['  total += exercise<%s>(buffer, size);' % name for name in types]
    lines += ['  return total + (getMD5Sum(0) != 0);', '}', '']
    with open(path, 'w') as stream:
        stream.write('\n'.join(lines))
    return len(types)
