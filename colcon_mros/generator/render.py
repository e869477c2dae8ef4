"""Render the empy templates in ``templates/`` from the type model, in the
C++ names :mod:`colcon_mros.generator.cpp` gives it.

Every function returns ``{relative path: text}`` (or the text) and touches no
file; writing is :mod:`colcon_mros.generator.output`'s job.
"""

import functools
import hashlib
import io
import os

import em

from colcon_mros import __version__
from colcon_mros.empy_proxy import allow_new_interpreter
from colcon_mros.generator.cpp import (SUPPORT_HEADER, SUPPORT_HEADERS, SUPPORT_VERSION,
                                       SUPPORT_VERSION_HEADER, CppMessage, CppService)

TEMPLATE_DIR = os.path.join(os.path.dirname(os.path.abspath(__file__)), 'templates')
# The static headers every export holds besides what is rendered.
SUPPORT_DIR = os.path.join(os.path.dirname(os.path.abspath(__file__)), 'support')


@functools.lru_cache(maxsize=None)
def _template_tokens(path):
    """The template at path, scanned into empy's tokens once per process:
    scanning is most of empy's work, and a run renders one template for
    every message."""
    with open(path) as template:
        scanner = em.Scanner(em.DEFAULT_PREFIX, template.read())
    return tuple(iter(scanner.one, None))


def render_template(template_dir, template_name, **context):
    """The text of the empy template template_name in template_dir."""
    allow_new_interpreter()
    tokens = _template_tokens(os.path.join(template_dir, template_name))
    output = io.StringIO()
    interpreter = em.Interpreter(output, globals=dict(context))
    try:
        interpreter.contexts.push(em.Context(template_name))
        for token in tokens:
            token.run(interpreter, None)
        interpreter.flush()
        return output.getvalue()
    finally:
        interpreter.shutdown()
        interpreter.unfix()


@functools.lru_cache(maxsize=None)
def _static(name):
    """The text of a static header in SUPPORT_DIR."""
    with open(os.path.join(SUPPORT_DIR, name)) as source:
        return source.read()


class Renderer:
    """Renders headers from one template directory (genmros -e chooses another)."""

    def __init__(self, template_dir=None):
        self.template_dir = template_dir or TEMPLATE_DIR

    def fingerprint(self, arguments, template_dirs=()):
        """What a run's output depends on besides the definitions: the
        genmros version, the templates (ours and those of template_dirs) and
        the run's arguments."""
        digest = hashlib.sha256(('%s\n%r\n' % (__version__, arguments)).encode())
        for directory in [self.template_dir, SUPPORT_DIR] + list(template_dirs):
            for name in sorted(os.listdir(directory)):
                with open(os.path.join(directory, name), 'rb') as stream:
                    digest.update(name.encode() + b'\0' + stream.read())
        return 'genmros %s\n' % digest.hexdigest()

    def support_headers(self):
        """The support headers: the static ones and their version header."""
        files = {name: _static(name) for name in SUPPORT_HEADERS if name != SUPPORT_VERSION_HEADER}
        files[SUPPORT_VERSION_HEADER] = render_template(
            self.template_dir, SUPPORT_VERSION_HEADER + '.em', support_version=SUPPORT_VERSION)
        return files

    def message(self, message):
        return {'%s.h' % message.full_name: render_template(
            self.template_dir, 'msg.h.em', msg=CppMessage(message), support_header=SUPPORT_HEADER,
            support_version=SUPPORT_VERSION, genmros_version=__version__)}

    def service(self, service):
        files = {'%s.h' % service.full_name: render_template(
            self.template_dir, 'srv.h.em', srv=CppService(service))}
        files.update(self.message(service.request))
        files.update(self.message(service.response))
        return files


def render_export_cmake(include_dir, types, cmake_module):
    """An export dir's mros_export.cmake (see :mod:`colcon_mros.export.export_dir`)."""
    return render_template(TEMPLATE_DIR, 'mros_export.cmake.em', include_dir=include_dir,
                           types=types, cmake_module=cmake_module)
