# SPDX-License-Identifier: BSD-3-Clause
"""The echo program of the mros2 tests: generated headers, really compiled.

:func:`build_echo` compiles testing/mros2_echo.cpp with the headers of an
mros2 export for a list of types (``pkg::msg::Type`` C++ names); an
:class:`Echo` sends it whole samples and reads back what the generated code
decoded and wrote again: alone, as the runtime sends it whole, in fragments,
and when published a second time.
"""

import os
import subprocess

SOURCE = os.path.join(os.path.dirname(os.path.abspath(__file__)), 'mros2_echo.cpp')
WARNING_FLAGS = ['-Wall', '-Wextra', '-pedantic', '-Werror']


def build_echo(include_dir, headers, cpp_names, out_dir, compiler=('g++',), std='c++11',
               extra_flags=()):
    """The echo program for the types cpp_names (their headers relative to
    include_dir), built in out_dir with compiler; returns its path."""
    os.makedirs(out_dir, exist_ok=True)
    types_header = os.path.join(out_dir, 'mros2_echo_types.h')
    with open(types_header, 'w') as stream:
        stream.write(''.join('#include "%s"\n' % header for header in sorted(set(headers))))
        stream.write('#define MROS2_ECHO_FUNCTIONS %s\n'
                     % ', '.join('echo<%s>' % name for name in cpp_names))
        stream.write('#define MROS2_ECHO_TYPE_NAMES %s\n'
                     % ', '.join('type_name<%s>' % name for name in cpp_names))
    program = os.path.join(out_dir, 'mros2_echo')
    command = list(compiler) + ['-std=' + std, '-O1'] + WARNING_FLAGS + list(extra_flags) + [
        '-I', include_dir, '-DMROS2_ECHO_TYPES_HEADER="%s"' % types_header, SOURCE,
        '-o', program]
    result = subprocess.run(command, capture_output=True, text=True)
    if result.returncode != 0:
        raise AssertionError('the echo program did not compile:\n%s' % result.stderr[-6000:])
    return program


class Echoed:
    """What the echo program wrote for one sample (bytes each), or refused."""

    def __init__(self, line):
        self.refused = line == 'refused'
        parts = [] if self.refused else [bytes.fromhex(part) for part in line.split(' ')]
        self.raw, self.whole, self.fragmented, self.again = parts or (None,) * 4


class Echo:
    """The echo program, run once for a batch of samples (optionally under qemu)."""

    def __init__(self, program, runner=()):
        self.command = list(runner) + [program]

    def type_names(self):
        """The DDS type name each type's header gives, in the program's order."""
        result = subprocess.run(self.command + ['names'], capture_output=True, text=True,
                                check=True)
        return result.stdout.split()

    def run(self, samples):
        """samples: (type index, fragment size, bytes) -> [Echoed]."""
        text = ''.join('%d %d %s\n' % (index, fragment, data.hex())
                       for index, fragment, data in samples)
        result = subprocess.run(self.command, input=text, capture_output=True, text=True,
                                timeout=300)
        if result.returncode != 0 or result.stderr:
            raise AssertionError('the echo program failed (%d): %s'
                                 % (result.returncode, result.stderr[-3000:]))
        lines = result.stdout.splitlines()
        assert len(lines) == len(samples), result.stdout[-2000:]
        return [Echoed(line) for line in lines]
