"""Render logic-free empy templates, and read the static support headers.

Every back end keeps its templates and static headers in a directory of its
own; this renders one template with the context a back end's C++ view
gives it, as genmsg's template_tools does, through empy's public
interpreter. Nothing is written here: writing is :mod:`.output`'s job.
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


def render_template(template_dir, template_name, **context):
    """The text of the empy template template_name in template_dir."""
    output = io.StringIO()
    interpreter = em.Interpreter(output=output, globals=dict(context))
    try:
        interpreter.string(_template_text(os.path.join(template_dir, template_name)),
                           template_name)
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
