"""Render the empy templates in ``templates/`` from the type model.

Every function returns ``{relative path: text}`` and touches no file; writing
is :mod:`colcon_mros.output`'s job.
"""

import os

import em

from colcon_mros.defaults import DEFAULT_VARIABLE_SIZE_BUDGET
from colcon_mros.model import SUPPORT_HEADER, MaxSize

TEMPLATE_DIR = os.path.join(os.path.dirname(os.path.abspath(__file__)), 'templates')


def _render(template_dir, template_name, **context):
    with open(os.path.join(template_dir, template_name)) as template:
        return em.expand(template.read(), dict(context))


class Renderer:
    """Renders headers from one template directory (genmros -e chooses another)."""

    def __init__(self, template_dir=None):
        self.template_dir = template_dir or TEMPLATE_DIR

    def support_header(self):
        with open(os.path.join(self.template_dir, SUPPORT_HEADER)) as source:
            return {SUPPORT_HEADER: source.read()}

    def message(self, message):
        return {'%s.h' % message.full_name: _render(
            self.template_dir, 'msg.h.em', msg=message, support_header=SUPPORT_HEADER)}

    def service(self, service):
        files = {'%s.h' % service.full_name: _render(self.template_dir, 'srv.h.em', srv=service)}
        files.update(self.message(service.request))
        files.update(self.message(service.response))
        return files

    def aggregates(self, messages, variable_budget=DEFAULT_VARIABLE_SIZE_BUDGET):
        """The per-firmware files the mROS v1 communication library includes."""
        return {
            'message_headers.h': _render(
                self.template_dir, 'message_headers.h.em', messages=messages),
            'message_class_specialization.h': _render(
                self.template_dir, 'message_class_specialization.h.em', messages=messages),
            'msg_max_size.h': _render(
                self.template_dir, 'msg_max_size.h.em', sizes=MaxSize(messages, variable_budget)),
        }
