# SPDX-License-Identifier: BSD-3-Clause
"""What the docs and docstrings name exists: every ``:mod:`` reference of
the package's docstrings is a module, and every ``genmros SUBCOMMAND`` the
README, docs/ and bench/README.md write as code (a code block or an inline
code span) is a subcommand of genmros."""

import glob
import os
import re

import pytest

from colcon_mros.cli import build_parser
from support.checkout import REPO

PACKAGE = os.path.join(REPO, 'colcon_mros')
DOCUMENTS = [os.path.join(REPO, 'README.md'), os.path.join(REPO, 'bench', 'README.md')] + \
    sorted(glob.glob(os.path.join(REPO, 'docs', '*.md')))
_MODULE_REFERENCE = re.compile(r':mod:`(?:[^`<]*<)?([.\w]+)>?`')
_CODE = re.compile(r'```.*?```|`[^`\n]+`', re.S)
# "a genmros export dir" (in a header's #error) names the export dir, not a subcommand.
_SUBCOMMAND = re.compile(r'\bgenmros ([a-z][a-z0-9]*(?:-[a-z0-9]+)*)\b(?! dir\b)')
# Prose in code: make's "$(error genmros not found: ...)", rosdep's "keys
# genmros and colcon-mros".
_NOT_SUBCOMMANDS = {'not', 'and'}


def _module_exists(name):
    path = os.path.join(REPO, *name.split('.'))
    return os.path.isfile(path + '.py') or os.path.isfile(os.path.join(path, '__init__.py'))


def _references():
    for path in sorted(glob.glob(os.path.join(PACKAGE, '**', '*.py'), recursive=True)):
        relative = os.path.relpath(path, REPO)[:-len('.py')].split(os.sep)
        package = relative[:-1]  # a module's own package (an __init__'s too)
        with open(path, encoding='utf-8') as stream:
            text = stream.read()
        for name in _MODULE_REFERENCE.findall(text):
            if name.startswith('.'):
                dots = len(name) - len(name.lstrip('.'))
                base = package[:len(package) - (dots - 1)]
                name = '.'.join(base + [name.lstrip('.')]) if name.lstrip('.') else '.'.join(base)
            yield os.path.relpath(path, REPO), name


def test_every_mod_reference_is_a_module():
    references = list(_references())
    assert len(references) > 20
    missing = ['%s: %s' % (path, name) for path, name in references if not _module_exists(name)]
    assert missing == []


@pytest.mark.parametrize('document', DOCUMENTS, ids=lambda path: os.path.relpath(path, REPO))
def test_every_subcommand_the_docs_name_exists(document):
    subcommands = set(build_parser()[1])
    with open(document, encoding='utf-8') as stream:
        code = '\n'.join(_CODE.findall(stream.read()))
    named = set(_SUBCOMMAND.findall(code))
    assert named - subcommands - _NOT_SUBCOMMANDS == set()
