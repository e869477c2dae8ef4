# SPDX-License-Identifier: BSD-3-Clause
"""The per-firmware aggregates: the files the mROS v1 library includes for
the message types of one firmware, rendered from the templates in
``templates/``, with the defaults of :mod:`.rules`.

- ``message_headers.h``: every type's header, the frame delivery
  (``mros_v1_delivery.h``) and the switch from a type ID to a callback's
  delivery and to the MD5 sum, which ros.cpp calls;
- ``message_class_specialization.h``: the instantiations of the API's
  templates, at the end of ros.cpp;
- ``msg_max_size.h``: ``PUB_MSG_MAX_SIZE``, with which the library sizes its
  publish buffer: the largest wire image of the firmware's types, and for
  each how it was found (exact, at most, or no maximum and which field has
  none);
- ``mros_v1_fit_check.h`` (:mod:`.fit_check_header`).
"""

from colcon_mros.core.render import render_template
from colcon_mros.mros_v1.cpp import CppType
from colcon_mros.mros_v1.defaults import DEFAULT_VARIABLE_SIZE_BUDGET
from colcon_mros.mros_v1.fit_check_header import FIT_CHECK_HEADER, fit_check_header
from colcon_mros.mros_v1.render import TEMPLATE_DIR
from colcon_mros.mros_v1.rules import DELIVERY_ON_STACK_MAX, FRAME_SLOTS, LIBRARY_PASSES_FRAME_SIZE

# Included by message_headers.h: memCopy() and delivery, which the support
# header only declares.
DELIVERY_HEADER = 'mros_v1_delivery.h'
# Each rendered from <name>.em.
RENDERED = ('message_headers.h', 'message_class_specialization.h', 'msg_max_size.h',
            DELIVERY_HEADER)
# What an export writes for one firmware besides the message headers.
FIRMWARE_FILES = RENDERED + (FIT_CHECK_HEADER,)
# What a run's output depends on here (an export's run record fingerprints them).
SOURCE_DIRS = (TEMPLATE_DIR,)


def _bytes(count):
    return '%d byte%s' % (count, '' if count == 1 else 's')


class MaxSizeEntry:
    """The publish buffer one message type needs."""

    def __init__(self, message, variable_budget):
        self.full_name = message.full_name
        if message.max_size is None:
            self.size = max(variable_budget, message.min_size)
            self.description = 'no maximum, %s has no bound; counted as %s' % (
                message.unbounded_reason, _bytes(self.size))
        elif message.is_fixed_size:
            self.size = message.max_size
            self.description = 'exactly %s' % _bytes(message.max_size)
        else:
            self.size = message.max_size
            self.description = 'at most %s' % _bytes(message.max_size)


class MaxSize:
    """PUB_MSG_MAX_SIZE for a firmware's message types."""

    def __init__(self, messages, variable_budget=DEFAULT_VARIABLE_SIZE_BUDGET):
        self.variable_budget = variable_budget
        self.entries = [MaxSizeEntry(message, variable_budget) for message in messages]
        self.max_size = max([entry.size for entry in self.entries] or [0])
        self.has_unbounded = any(message.max_size is None for message in messages)


def firmware_files(messages, variable_budget=DEFAULT_VARIABLE_SIZE_BUDGET):
    """{FIRMWARE_FILES name: text} for a firmware's message types (the
    ROS 1 front end's models)."""
    context = {'messages': [CppType(message.full_name) for message in messages],
               'sizes': MaxSize(messages, variable_budget),
               'delivery_header': DELIVERY_HEADER,
               'fit_check_header': FIT_CHECK_HEADER,
               'frame_size_macro': LIBRARY_PASSES_FRAME_SIZE,
               'frame_slots_setting': FRAME_SLOTS.setting,
               'default_frame_slots': FRAME_SLOTS.default,
               'on_stack_max': DELIVERY_ON_STACK_MAX}
    files = {name: render_template(TEMPLATE_DIR, name + '.em', **context) for name in RENDERED}
    files.update(fit_check_header(messages))
    return files
