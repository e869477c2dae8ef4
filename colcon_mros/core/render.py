"""Render logic-free empy templates, and read the static support headers.

Every back end keeps its templates and static headers in a directory of its
own; this renders one template with the context a back end's C++ view
gives it, through an empy 3 interpreter as genmsg's template_tools does.
Nothing is written here: writing is :mod:`.output`'s job.

Scanning a template into empy's tokens is half of an export's time (an
export renders msg.h.em once per type: bench/README.md), so each template
is scanned once per process and its tokens run in a new interpreter for
each render. tests/core/test_render.py pins what this relies on: tokens
that run again give the same text as the interpreter's own string().
"""

import functools
import io
import os

import em

# The static headers both back ends' exports hold: the containers of
# bounded storage (mros_message_containers.h).
SUPPORT_DIR = os.path.join(os.path.dirname(os.path.abspath(__file__)), 'support')


@functools.lru_cache(maxsize=None)
def _template_text(path):
    with open(path) as template:
        return template.read()


@functools.lru_cache(maxsize=None)
def _template_tokens(path):
    """The template at path scanned into empy's tokens, once per process."""
    scanner = em.Scanner(em.DEFAULT_PREFIX, _template_text(path))
    return tuple(iter(scanner.one, None))


def render_template(template_dir, template_name, **context):
    """The text of the empy template template_name in template_dir."""
    output = io.StringIO()
    interpreter = em.Interpreter(output=output, globals=dict(context))
    try:
        interpreter.contexts.push(em.Context(template_name))
        for token in _template_tokens(os.path.join(template_dir, template_name)):
            token.run(interpreter, None)
        interpreter.flush()
        return output.getvalue()
    finally:
        interpreter.shutdown()


@functools.lru_cache(maxsize=None)
def static_text(directory, name):
    """The text of a static header: directory's, else the core's SUPPORT_DIR."""
    for where in (directory, SUPPORT_DIR):
        path = os.path.join(where, name)
        if os.path.isfile(path):
            with open(path) as source:
                return source.read()
    raise FileNotFoundError(os.path.join(directory, name))
