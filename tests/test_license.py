# SPDX-License-Identifier: BSD-3-Clause
"""The license, stated once and everywhere alike: LICENSE (BSD-3-Clause with
the exception that frees genmros' output of the notice), one SPDX line at the
top of every source file, and setup.cfg and debian/copyright saying the same."""

import configparser
import glob
import os
import re
import subprocess

import pytest

from colcon_mros.core.output import is_generated
from colcon_mros.core.render import render_template
from support.checkout import REPO

SPDX = 'SPDX-License-Identifier: BSD-3-Clause'
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


def _read(*path):
    with open(os.path.join(REPO, *path), encoding='utf-8') as stream:
        return stream.read()


def _source_files():
    """(path, the comment starts its kind allows) of every tracked source file."""
    try:
        listed = subprocess.run(['git', 'ls-files'], cwd=REPO, capture_output=True, text=True,
                                check=True).stdout.splitlines()
    except (OSError, subprocess.CalledProcessError):
        pytest.skip('not a git checkout')
    sources = []
    for path in listed:
        if path.startswith(LEFT_ALONE) or '/patches/' in path:
            continue
        for ending, starts in COMMENTS.items():
            if os.path.basename(path) == ending or path.endswith(ending) and ending[0] == '.':
                sources.append((path, starts if isinstance(starts, tuple) else (starts,)))
                break
    return sources


def test_every_source_file_states_the_license_at_its_top():
    sources = _source_files()
    assert len(sources) > 350
    missing = []
    for path, starts in sources:
        lines = _read(path).splitlines()
        if lines and lines[0].startswith('#!'):
            lines = lines[1:]
        if not any(line.startswith(start + SPDX) for line in lines[:2] for start in starts):
            missing.append(path)
    assert missing == []


def test_license_is_bsd_3_clause_with_the_exception_for_generated_output():
    text = _read('LICENSE')
    assert text.startswith('Copyright (c) 2026, the colcon-mros authors\n')
    assert 'Redistribution and use in source and binary forms' in text
    assert '3. Neither the name of the copyright holder' in text
    assert '\nException for generated output\n' in text
    words = ' '.join(text.split())
    assert 'colcon_mros/*/templates/' in words
    assert 'colcon_mros/*/support/' in words
    assert ('may be used, copied, modified and distributed, in source or binary form, for any '
            'purpose, without restriction and without the conditions above') in words
    # The exception names every support header there is.
    for path in SUPPORT_HEADERS:
        assert os.path.basename(path) in words


def test_setup_cfg_and_debian_copyright_agree_with_license():
    setup = configparser.ConfigParser()
    setup.read(os.path.join(REPO, 'setup.cfg'))
    assert setup['metadata']['license'] == 'BSD-3-Clause'
    copyright = _read('debian', 'copyright')
    paragraphs = {}
    for paragraph in copyright.strip().split('\n\n'):
        fields = dict(re.findall(r'^([A-Za-z-]+): ?(.*(?:\n .*)*)', paragraph, re.M))
        key = 'Files: ' + fields['Files'] if 'Files' in fields else 'License: ' + \
            fields.get('License', '').split('\n')[0]
        paragraphs[key] = fields
    # Source is this project's, not mROS' repository.
    header = copyright.split('\n\n')[0]
    assert re.search(r'^Source: (?!.*mROS)\S+$', header, re.M), header
    assert paragraphs['Files: *']['License'] == setup['metadata']['license']
    assert paragraphs['Files: *']['Copyright'] == '2026 the colcon-mros authors'
    exception = 'BSD-3-Clause with genmros-output exception'
    assert paragraphs['Files: colcon_mros/*/support/*']['License'] == exception

    def body(name):
        """A License paragraph's text as LICENSE words it."""
        lines = paragraphs['License: ' + name]['License'].split('\n')[1:]
        return ' '.join(' '.join(line[1:] for line in lines if line != ' .').split())

    license_text = _read('LICENSE')
    bsd, _, exception_text = license_text.partition('\nException for generated output\n')
    bsd = ' '.join(bsd.split('\n', 2)[2].split())
    assert body('BSD-3-Clause') == bsd
    assert body(exception) == bsd + ' Exception for generated output ' + ' '.join(
        exception_text.split())


def test_the_support_headers_still_read_as_genmros_output():
    # The license lines come first; the marker an export's clean-up looks for
    # stays within the part it reads.
    assert len(SUPPORT_HEADERS) == 4
    for path in SUPPORT_HEADERS:
        with open(path) as stream:
            second = stream.read().splitlines()[1]
        assert second.startswith('// Generated by genmros;') and 'LICENSE' in second
        assert is_generated(path), path


@pytest.mark.parametrize('template', TEMPLATES, ids=os.path.basename)
def test_a_templates_license_lines_render_nothing(template, tmp_path):
    # Its leading empy comments alone, as a template of their own.
    with open(template) as stream:
        head = stream.read().splitlines(True)[:2]
    assert head[0] == '@# %s\n' % SPDX
    (tmp_path / 'head.em').write_text(''.join(head))
    assert render_template(str(tmp_path), 'head.em') == ''
