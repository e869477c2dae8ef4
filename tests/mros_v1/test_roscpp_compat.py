# SPDX-License-Identifier: BSD-3-Clause
"""genmros headers against roscpp and gencpp, for every Debian ROS message package.

The expected values come from the real roscpp serializer and the gencpp
headers of Debian's lib*-msgs-dev packages, never from genmros itself.
"""

import glob
import os
import subprocess

import pytest

from support import cpp_harness
from support.debian_messages import DEBIAN_MESSAGE_PACKAGES
from testing import ros_paths

pytestmark = pytest.mark.slow

INSTANCES_PER_TYPE = 200


@pytest.fixture(scope='module')
def debian_types():
    messages = []
    services = []
    for package in DEBIAN_MESSAGE_PACKAGES:
        for path in ros_paths.ros1_definitions(package, 'msg'):
            messages.append('%s/%s' % (package, os.path.basename(path)[:-4]))
        services.extend((package, path) for path in ros_paths.ros1_definitions(package, 'srv'))
    return cpp_harness.TypeSet(cpp_harness.search_path(with_test_ws=False), messages, services)


@pytest.fixture(scope='module')
def harness_sources(debian_types, debian_export, tmp_path_factory):
    directory = str(tmp_path_factory.mktemp('roscpp_harness'))
    return directory, cpp_harness.write_sources(directory, debian_types)


def test_debian_packages_cover_every_message_package(debian_types):
    # About 160 definition files; a missing package would shrink the check silently.
    files = len([t for t in debian_types.messages if not t.endswith(('Request', 'Response'))])
    assert files >= 140
    assert len(debian_types.services) >= 15


def test_all_headers_compile_together_without_warnings(debian_export, tmp_path):
    headers = sorted(os.path.relpath(p, debian_export)
                     for p in glob.glob(os.path.join(debian_export, '**', '*.h'), recursive=True))
    assert len(headers) > 180
    source = tmp_path / 'all_headers.cpp'
    source.write_text(''.join('#include <%s>\n' % h for h in headers
                              if h != 'message_class_specialization.h')
                      + 'int main() { return 0; }\n')
    result = subprocess.run(['g++', '-std=c++11', '-Wall', '-Wextra', '-Werror', '-pedantic',
                             '-fsyntax-only', '-I', debian_export, str(source)],
                            capture_output=True, text=True)
    assert result.returncode == 0, result.stderr[-4000:]


def test_bytes_md5_and_definitions_equal_roscpp(harness_sources, debian_export):
    directory, sources = harness_sources
    objects = [
        cpp_harness.compile_object(sources['roscpp_side.cpp'],
                                   directory, [directory], strict=False),
        cpp_harness.compile_object(sources['mros_side.cpp'], directory, [
                                   debian_export, directory]),
        cpp_harness.compile_object(
            os.path.join(cpp_harness.RANDOM_HEADER_DIR, 'compare_with_roscpp.cpp'),
            directory, [directory]),
    ]
    program = cpp_harness.link_program(objects, os.path.join(directory, 'compare_with_roscpp'),
                                       libraries=cpp_harness.ROSCPP_LIBRARIES)
    result = subprocess.run([program, str(INSTANCES_PER_TYPE)], capture_output=True, text=True)
    assert result.returncode == 0, result.stdout[-6000:] + result.stderr[-2000:]
    assert ': 0 mismatches' in result.stdout
