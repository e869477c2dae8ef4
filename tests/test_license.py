# SPDX-License-Identifier: BSD-3-Clause
"""The license, stated once and everywhere alike: LICENSE (BSD-3-Clause), the
support headers MIT-0 (LICENSES/MIT-0.txt), what genmros renders without any
copyright notice, one SPDX line at the top of every source file, and setup.cfg
and debian/copyright saying the same, the patch series' upstream licenses too."""

import configparser
import fnmatch
import glob
import itertools
import os
import re
import subprocess

import pytest

from colcon_mros.core.output import GENERATED_MARKER, is_generated
from colcon_mros.core.render import render_template
from colcon_mros.export.export_dir import ExportDir
from support.checkout import REPO, TEST_WS, run_genmros
from testing.ros_paths import prefix_arguments, ros1_prefixes

PROJECT_LICENSE = 'BSD-3-Clause'
SUPPORT_LICENSE = 'MIT-0'
SPDX = 'SPDX-License-Identifier: '
# What every file genmros renders says of itself, as rosidl_generator_cpp's
# output does.
NO_NOTICE = 'Generated code does not contain a copyright notice.'
# How each kind of source file says it, by the end of its name.
COMMENTS = {
    '.py': '# ', '.sh': '# ', '.cmake': '# ', '.cmake.in': '# ', '.mk': '# ',
    'CMakeLists.txt': '# ', 'Makefile': '# ',
    '.c': '/* ', '.cfg': '/* ', '.ld': '/* ',
    '.h': ('// ', '/* '), '.hpp': '// ', '.cpp': ('// ', '/* '), '.inc': '// ',
    '.em': '@# ',
}
# Not marked: the Debian packaging (debian/copyright says it all), setup.cfg
# (its license field does; .cfg is otherwise TOPPERS' kernel configuration),
# the CI runner, patch series and the patch tests' trees, whose bytes and line
# numbers the patches and their tests depend on.
LEFT_ALONE = ('debian/', 'setup.cfg', '.ci/', 'tests/fixtures/patch_tree/')
SUPPORT_HEADERS = sorted(glob.glob(os.path.join(REPO, 'colcon_mros', '*', 'support', '*')))
TEMPLATES = sorted(glob.glob(os.path.join(REPO, 'colcon_mros', '*', 'templates', '*.em')))
# The templates that render a part of an mros2 header (header.hpp.em's body),
# not a file: the header says it for them.
HEADER_PARTS = {'message_class.hpp.em', 'service_types.hpp.em', 'type_name.hpp.em'}
MROS_V1_PATCHES = os.path.join('colcon_mros', 'library_tools', 'mros_v1', 'patches')
MROS2_PATCHES = os.path.join('colcon_mros', 'library_tools', 'mros2', 'patches')
# The license of what a patch changes, by the library its paths name: mROS v1
# is TOPPERS (mROS-base/mROS' LICENSE), mros2 Apache-2.0 and its embeddedRTPS
# MIT.
EMBEDDED_RTPS = 'embeddedRTPS/'


def _read(*path):
    with open(os.path.join(REPO, *path), encoding='utf-8') as stream:
        return stream.read()


def _words(text):
    return ' '.join(text.split())


def _tracked_files():
    try:
        return subprocess.run(['git', 'ls-files'], cwd=REPO, capture_output=True, text=True,
                              check=True).stdout.splitlines()
    except (OSError, subprocess.CalledProcessError):
        pytest.skip('not a git checkout')


def _source_files():
    """(path, the comment starts its kind allows) of every tracked source file."""
    sources = []
    for path in _tracked_files():
        if path.startswith(LEFT_ALONE) or '/patches/' in path:
            continue
        for ending, starts in COMMENTS.items():
            if os.path.basename(path) == ending or path.endswith(ending) and ending[0] == '.':
                sources.append((path, starts if isinstance(starts, tuple) else (starts,)))
                break
    return sources


def _is_support_header(path):
    return os.path.join(REPO, path) in SUPPORT_HEADERS


def test_every_source_file_states_its_license_at_its_top():
    sources = _source_files()
    assert len(sources) > 350
    missing = []
    for path, starts in sources:
        spdx = SPDX + (SUPPORT_LICENSE if _is_support_header(path) else PROJECT_LICENSE)
        lines = _read(path).splitlines()
        if lines and lines[0].startswith('#!'):
            lines = lines[1:]
        if not any(line.startswith(start + spdx) for line in lines[:2] for start in starts):
            missing.append(path)
    assert missing == []


def test_license_is_bsd_3_clause_and_names_the_support_headers_mit_0():
    text = _read('LICENSE')
    assert text.startswith('Copyright (c) 2026, the colcon-mros authors\n')
    assert 'Redistribution and use in source and binary forms' in text
    assert '3. Neither the name of the copyright holder' in text
    assert 'exception' not in text.lower()
    pointer = text.split('POSSIBILITY OF SUCH DAMAGE.\n', 1)[1]
    assert _words(pointer) == ('The support headers in colcon_mros/*/support/ are MIT-0 instead '
                               '(LICENSES/MIT-0.txt).')
    mit_0 = _read('LICENSES', 'MIT-0.txt')
    assert mit_0.startswith('MIT No Attribution\n\nCopyright 2026 the colcon-mros authors\n')
    assert 'subject to the following conditions' not in mit_0  # MIT's, the notice MIT-0 drops


def _copyright_paragraphs():
    """debian/copyright's paragraphs: [{field: value}], in order."""
    paragraphs = []
    for paragraph in _read('debian', 'copyright').strip().split('\n\n'):
        paragraphs.append(dict(re.findall(r'^([A-Za-z-]+): ?(.*(?:\n .*)*)', paragraph, re.M)))
    return paragraphs


def _license_text(paragraph):
    """A License paragraph's text, its lines and blank lines joined as words."""
    lines = paragraph['License'].split('\n')[1:]
    return _words(' '.join(line[1:] for line in lines if line != ' .'))


def test_setup_cfg_and_debian_copyright_agree_with_license():
    setup = configparser.ConfigParser()
    setup.read(os.path.join(REPO, 'setup.cfg'))
    assert setup['metadata']['license'] == PROJECT_LICENSE
    paragraphs = _copyright_paragraphs()
    header = paragraphs[0]
    # Source is this project's, not mROS' repository.
    assert re.match(r'(?!.*mROS)\S+$', header['Source']), header['Source']
    files = {paragraph['Files']: paragraph for paragraph in paragraphs if 'Files' in paragraph}
    licenses = {paragraph['License'].split('\n')[0]: paragraph for paragraph in paragraphs
                if set(paragraph) == {'License'}}
    assert files['*']['License'] == PROJECT_LICENSE
    assert files['*']['Copyright'] == '2026 the colcon-mros authors'
    assert files['colcon_mros/*/support/*']['License'] == SUPPORT_LICENSE
    assert files['colcon_mros/*/support/*']['Copyright'] == '2026 the colcon-mros authors'

    bsd = _words(_read('LICENSE').split('\n', 2)[2].split('POSSIBILITY OF SUCH DAMAGE.')[0])
    assert _license_text(licenses[PROJECT_LICENSE]) == bsd + ' POSSIBILITY OF SUCH DAMAGE.'
    mit_0 = _words(_read('LICENSES', 'MIT-0.txt').split('\n', 4)[4])
    assert _license_text(licenses[SUPPORT_LICENSE]) == mit_0
    # Every license a Files paragraph names has its paragraph, and no other.
    named = {name for paragraph in files.values() for name in paragraph['License'].split(' and ')}
    assert named == set(licenses)
    assert 'exception' not in _read('debian', 'copyright').lower()


def _patch_licenses(path):
    """The licenses of the libraries a patch changes, as debian/copyright names them."""
    if path.startswith(MROS_V1_PATCHES):
        return 'TOPPERS'
    changed = re.findall(r'^\+\+\+ b/(\S+)', _read(path), re.M)
    assert changed, path
    rtps = any(name.startswith(EMBEDDED_RTPS) for name in changed)
    mros2 = any(not name.startswith(EMBEDDED_RTPS) for name in changed)
    return ' and '.join(name for name, touched in (('MIT', rtps), ('Apache-2.0', mros2))
                        if touched)


def test_debian_copyright_gives_each_patch_its_upstreams_license():
    """The last Files paragraph that matches a file is the one that applies; its
    patterns' * matches a / too, as fnmatch's does."""
    tracked = _tracked_files()
    patches = [path for path in tracked for directory in (MROS_V1_PATCHES, MROS2_PATCHES)
               if fnmatch.fnmatchcase(path, os.path.join(directory, '*.patch'))]
    assert len(patches) > 30
    applying = {}
    for paragraph in (p for p in _copyright_paragraphs() if 'Files' in p):
        for pattern in paragraph['Files'].split():
            matches = fnmatch.filter(tracked, pattern)
            assert matches, pattern  # each file named exists
            applying.update((path, paragraph) for path in matches)
    for patch in patches:
        assert applying[patch]['License'] == _patch_licenses(patch), patch
        assert '2026 the colcon-mros authors' in applying[patch]['Copyright'], patch
    # Only the patches themselves quote upstream: the series files are genmros' own.
    for directory in (MROS_V1_PATCHES, MROS2_PATCHES):
        assert applying[os.path.join(directory, 'series')]['License'] == PROJECT_LICENSE


def test_the_support_headers_still_read_as_genmros_output():
    # The license line comes first; the marker an export's clean-up looks for
    # stays within the part it reads.
    assert len(SUPPORT_HEADERS) == 4
    for path in SUPPORT_HEADERS:
        with open(path) as stream:
            first, second = stream.read().splitlines()[:2]
        assert first == '// ' + SPDX + SUPPORT_LICENSE
        assert second.startswith('// Generated by genmros;') and SUPPORT_LICENSE in second
        assert is_generated(path), path


@pytest.mark.parametrize('template', TEMPLATES, ids=os.path.basename)
def test_a_templates_license_line_renders_nothing(template, tmp_path):
    # Its leading empy comments alone, as a template of their own.
    with open(template) as stream:
        lines = stream.read().splitlines(True)
    assert lines[0] == '@# %s%s\n' % (SPDX, PROJECT_LICENSE)
    comments = next(i for i, line in enumerate(lines) if not line.startswith('@#'))
    (tmp_path / 'head.em').write_text(''.join(lines[:comments]))
    assert render_template(str(tmp_path), 'head.em') == ''


@pytest.mark.parametrize('template', TEMPLATES, ids=os.path.basename)
def test_every_template_of_a_file_says_it_has_no_copyright_notice(template):
    # The rendered files below come from some of them; this holds a new one to it.
    if os.path.basename(template) in HEADER_PARTS:
        return
    with open(template) as stream:
        assert NO_NOTICE in stream.read()


def _leading_comment(path, text):
    """The comment a rendered file starts with."""
    if path.endswith('.xml'):
        return text.split('-->')[0]
    start = '# ' if path.endswith('.cmake') else '//'
    return ''.join(itertools.takewhile(lambda line: line.startswith(start),
                                       text.splitlines(True)))


@pytest.fixture(scope='module')
def firmware_files(tmp_path_factory):
    """{path: text} of what genmros writes for a firmware: both back ends'
    exports (messages, a service, the aggregates, the support headers), the
    peer profile and an export dir's mros_export.cmake."""
    root = tmp_path_factory.mktemp('firmware')
    run_genmros('export', '--workspace', TEST_WS, '--type', 'mros_test/NestedTypes',
                '--type', 'mros_test/LookupPerson', '-o', str(root / 'mros_v1'),
                *prefix_arguments(ros1_prefixes()))
    run_genmros('mros2-export', '--workspace', os.path.join(REPO, 'test_ws_ros2'),
                '--package', 'mros2_test_msgs', '--publish', 'mros2_test_msgs/msg/Reading',
                '-o', str(root / 'mros2'))
    run_genmros('mros2-peer-profile', '--max-message', '1472', '-o', str(root / 'profile.xml'))
    ExportDir(str(root / 'export_dir')).prepare('/opt/genmros/mros_generate.cmake')
    files = {}
    for path in glob.glob(str(root / '**' / '*'), recursive=True):
        if os.path.isfile(path) and path.endswith(('.h', '.hpp', '.cmake', '.xml')):
            with open(path, encoding='utf-8') as stream:
                files[os.path.relpath(path, str(root))] = stream.read()
    return files


def test_a_firmware_gets_no_license_but_the_support_headers_mit_0(firmware_files):
    support = {os.path.basename(path): _read(path) for path in SUPPORT_HEADERS}
    names = {os.path.basename(path) for path in firmware_files}
    assert {'message_headers.h', 'msg_max_size.h', 'mros_v1_delivery.h', 'mros_v1_fit_check.h',
            'message_class_specialization.h', 'mros_message_support_version.h',
            'LookupPerson.h', 'NestedTypes.h', 'templates.hpp', 'reading.hpp', 'query.hpp',
            'profile.xml', 'mros_export.cmake'} | set(support) <= names
    for path, text in firmware_files.items():
        name = os.path.basename(path)
        if name in support:
            assert text == support[name], path  # a byte copy: MIT-0, in its first line
            continue
        assert 'SPDX' not in text and 'BSD' not in text and 'LICENSE' not in text, path
        assert NO_NOTICE in _leading_comment(path, text), path
        assert GENERATED_MARKER in text[:512], path  # what is_generated reads
