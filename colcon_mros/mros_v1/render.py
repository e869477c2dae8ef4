# SPDX-License-Identifier: BSD-3-Clause
"""Render the mROS v1 headers from the ROS 1 type model, in the C++ names
:mod:`colcon_mros.mros_v1.cpp` gives it.

The templates in ``templates/`` hold no logic; the static support headers
are in ``support/`` (and the containers header in the core's). Every
function returns ``{relative path: text}`` (or the text) and touches no
file; writing is :mod:`colcon_mros.core.output`'s job.
"""

import hashlib
import os

from colcon_mros import __version__
from colcon_mros.core.render import SUPPORT_DIR as CORE_SUPPORT_DIR
from colcon_mros.core.render import render_template, static_text
from colcon_mros.mros_v1.cpp import (SUPPORT_HEADER, SUPPORT_HEADERS, SUPPORT_VERSION,
                                     SUPPORT_VERSION_HEADER, CppMessage, CppService)

TEMPLATE_DIR = os.path.join(os.path.dirname(os.path.abspath(__file__)), 'templates')
# The static headers every export holds besides what is rendered.
SUPPORT_DIR = os.path.join(os.path.dirname(os.path.abspath(__file__)), 'support')


class Renderer:
    """Renders headers from one template directory (genmros -e chooses another)."""

    def __init__(self, template_dir=None):
        self.template_dir = template_dir or TEMPLATE_DIR

    def fingerprint(self, arguments, template_dirs=()):
        """What a run's output depends on besides the definitions: the
        genmros version, the templates (ours and those of template_dirs), the
        static headers and the run's arguments."""
        digest = hashlib.sha256(('%s\n%r\n' % (__version__, arguments)).encode())
        for directory in [self.template_dir, SUPPORT_DIR, CORE_SUPPORT_DIR] + list(template_dirs):
            for name in sorted(os.listdir(directory)):
                with open(os.path.join(directory, name), 'rb') as stream:
                    digest.update(name.encode() + b'\0' + stream.read())
        return 'genmros %s\n' % digest.hexdigest()

    def support_headers(self):
        """The support headers: the static ones and their version header."""
        files = {name: static_text(SUPPORT_DIR, name)
                 for name in SUPPORT_HEADERS if name != SUPPORT_VERSION_HEADER}
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
