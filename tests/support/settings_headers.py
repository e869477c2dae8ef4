# SPDX-License-Identifier: BSD-3-Clause
"""mROS v1 settings headers for the fit check's tests: the small ones in
tests/fixtures/mros_v1_settings, copies of them with values changed, and a
#define's value read by hand (not by genmros' reader, which is under test)."""

import os
import re

from support.checkout import FIXTURES

SMALL_SETTINGS = os.path.join(FIXTURES, 'mros_v1_settings')
# In the order the build includes them.
HEADERS = ('mros_usr_config.h', 'mros_packet_config.h')


def small_settings(directory=None, **values):
    """The directory of the small settings headers: the fixture's, or a
    copy of them in directory with values ({name: number}) changed."""
    if directory is None:
        return SMALL_SETTINGS
    os.makedirs(str(directory), exist_ok=True)
    for name in HEADERS:
        with open(os.path.join(SMALL_SETTINGS, name)) as stream:
            text = stream.read()
        for setting, value in values.items():
            text = re.sub(r'(#define %s )\S+' % setting, r'\g<1>%d' % value, text)
        with open(os.path.join(str(directory), name), 'w') as stream:
            stream.write(text)
    return str(directory)


def header_paths(directory):
    """The settings headers of directory, in HEADERS' order."""
    return [os.path.join(directory, name) for name in HEADERS]


def define(paths, name):
    """(value, path, line) of the first #define of name in paths."""
    for path in paths:
        with open(path) as stream:
            for number, line in enumerate(stream, 1):
                match = re.match(r'\s*#\s*define\s+%s\s+\(?(\d+)' % name, line)
                if match:
                    return int(match.group(1)), path, number
    raise AssertionError('no #define %s in %s' % (name, ', '.join(paths)))
