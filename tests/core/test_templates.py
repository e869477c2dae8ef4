# SPDX-License-Identifier: BSD-3-Clause
"""Every template of the package holds no logic (gencpp's rule, and ours:
a back end's C++ view computes, its templates only lay out): expressions
are names and attributes, control is for over one and if over one (or its
negation), and no template runs a statement of its own. A template that
needs more than that asks its C++ view for it."""

import glob
import os

import pytest

from colcon_mros.core.render import compiled_template
from support.checkout import REPO

TEMPLATES = sorted(glob.glob(os.path.join(REPO, 'colcon_mros', '*', 'templates', '*.em')))


def test_there_are_templates_of_every_back_end_and_the_export():
    assert {os.path.basename(os.path.dirname(os.path.dirname(path))) for path in TEMPLATES} == {
        'mros_v1', 'mros2', 'export'}


@pytest.mark.parametrize('path', TEMPLATES, ids=lambda path: os.path.relpath(path, REPO))
def test_the_template_holds_no_logic(path):
    """colcon_mros.core.render compiles only a template without logic."""
    assert compiled_template(path) is not None


@pytest.mark.parametrize('logic', [
    '@{x = 1}', '@(len(items))', '@(a + b)', '@name.attr', '@(a ? b ! c)',
    '@[for i in range(3)]@(i)@[end for]', '@[if a == b]@[end if]', '@[while x]@[end while]',
    '@[for m in msg.members]@[else]@[end for]', '@[if x]@[else]@[elif y]@[end if]',
    '@[if x]', '@[end if]', '@[if x]@[end for]'])
def test_the_check_sees_logic(tmp_path, logic):
    """logic after a template without any."""
    logic_free = ('@(msg.name) @[if not msg.ok]@[elif msg.other]@[else]@[end if]\n'
                  '@[for a, b in msg.pairs]@(a)@[end for]\n')
    for name, text, compiles in [('logic_free.em', logic_free, True),
                                 ('logic.em', logic_free + logic, False)]:
        (tmp_path / name).write_text(text)
        assert (compiled_template(str(tmp_path / name)) is not None) == compiles, name
