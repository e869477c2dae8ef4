# SPDX-License-Identifier: BSD-3-Clause
"""Every template of the package holds no logic (gencpp's rule, and ours:
a back end's C++ view computes, its templates only lay out): expressions
are names and attributes, control is for over one and if over one (or its
negation), and no template runs a statement of its own. A template that
needs more than that asks its C++ view for it."""

import glob
import os
import re

import em
import pytest

from support.checkout import REPO

TEMPLATES = sorted(glob.glob(os.path.join(REPO, 'colcon_mros', '*', 'templates', '*.em')))
_DOTTED = r'[A-Za-z_]\w*(?:\.[A-Za-z_]\w*)*'
_ALLOWED_CONTROL = {
    'for': re.compile(r'^[A-Za-z_]\w*(?:\s*,\s*[A-Za-z_]\w*)*\s+in\s+%s$' % _DOTTED),
    'if': re.compile(r'^(?:not\s+)?%s$' % _DOTTED),
    'elif': re.compile(r'^(?:not\s+)?%s$' % _DOTTED),
}


def _tokens(tokens):
    for token in tokens:
        yield token
        yield from _tokens(getattr(token, 'subtokens', ()))


def _logic(path):
    """What in the template at path is more than a name or a plain for/if."""
    with open(path) as stream:
        scanner = em.Scanner(em.DEFAULT_PREFIX, stream.read())
    found = []
    for token in _tokens(iter(scanner.one, None)):
        if isinstance(token, (em.StatementToken, em.InPlaceToken, em.CustomToken)):
            found.append(token.string())
        elif isinstance(token, em.ExpressionToken):
            if (not re.match('^%s$' % _DOTTED, token.testCode.strip())
                    or token.thenCode or token.elseCode or token.exceptCode):
                found.append(token.string())
        elif isinstance(token, em.SimpleExpressionToken):
            if not re.match('^%s$' % _DOTTED, token.code):
                found.append(token.string())
        elif isinstance(token, em.ControlToken):
            if token.type in _ALLOWED_CONTROL:
                if not _ALLOWED_CONTROL[token.type].match(token.rest.strip()):
                    found.append('@[%s]' % token.contents)
            elif token.type not in ('else', 'end'):
                found.append('@[%s]' % token.contents)
    return found


def test_there_are_templates_of_every_back_end_and_the_export():
    assert {os.path.basename(os.path.dirname(os.path.dirname(path))) for path in TEMPLATES} == {
        'mros_v1', 'mros2', 'export'}


@pytest.mark.parametrize('path', TEMPLATES, ids=lambda path: os.path.relpath(path, REPO))
def test_the_template_holds_no_logic(path):
    assert _logic(path) == []


def test_the_check_sees_logic(tmp_path):
    template = tmp_path / 'logic.em'
    template.write_text('@{x = 1}@(len(items)) @(a + b) @name.attr @(msg.name)\n'
                        '@[for i in range(3)]@(i)@[end for]@[for m in msg.members]@[end for]\n'
                        '@[if a == b]@[elif not msg.ok]@[else]@[end if]@[while x]@[end while]\n')
    assert _logic(str(template)) == ['@{x = 1}', '@(len(items))', '@(a + b)',
                                     '@[for i in range(3)]', '@[if a == b]', '@[while x]']
