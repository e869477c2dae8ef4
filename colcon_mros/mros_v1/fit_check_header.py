# SPDX-License-Identifier: BSD-3-Clause
"""``mros_v1_fit_check.h``: the rule table rendered as compile-time checks.

The same :data:`.rules.RULES` the Python fit check (:mod:`.fit`) applies,
rendered as one ``#if``/``#error`` per type and rule, which the
preprocessor evaluates where the library's own settings headers are on the
include path (ros.cpp's compile): a firmware whose types the library is
certain to overrun does not build for the board, whatever build tool made
its headers. A connection header counts with the shortest names, as the
Python check's errors do. It also holds on-board delivery's table of waiting
frames (mros_v1_delivery.h, where the library passes no frame size) to the
number of blocks the publishing pools have (:data:`.rules.FRAME_SLOTS`).
"""

from colcon_mros.core.render import render_template
from colcon_mros.mros_v1.render import TEMPLATE_DIR
from colcon_mros.mros_v1.rules import (FRAME_SLOTS, LIBRARY_HEADER_GUARD,
                                       LIBRARY_PASSES_FRAME_SIZE, PACKET_CONFIG, POOL_KINDS, RULES,
                                       SETTINGS_HEADERS, USR_CONFIG, FirmwareNeeds)

FIT_CHECK_HEADER = 'mros_v1_fit_check.h'


class Check:
    """One rule for one type: the #if condition that fails the build, and
    the #error's message."""

    def __init__(self, rule, needs):
        amount = rule.amount(needs)
        what = rule.describe(needs)
        if rule.is_pool:
            self.failure = '!%s(%d)' % (rule.setting.holds_macro, amount)
            needed = 'a %s >= %d' % (rule.setting_name, amount)
        elif rule.with_names:
            # What the header needs for certain: with the shortest names.
            self.failure = '%s < %d' % (rule.setting, rule.certain(needs))
            needed = "%s >= %d + the topic and caller id's bytes" % (rule.setting, amount)
        else:
            self.failure = '%s < %d' % (rule.setting, amount)
            needed = '%s >= %d' % (rule.setting, amount)
        self.message = '%s: %s needs %s (%s)' % (needs.full_name, what, needed, rule.header)


class CheckedType:
    """One type's checks, and what a firmware engineer reads above them."""

    def __init__(self, needs):
        frame = ('no largest frame' if needs.max_frame is None
                 else 'a largest frame of %d bytes' % needs.max_frame)
        self.comment = '%s: definition text %d bytes, name %d with its NUL, %s.' % (
            needs.full_name, needs.text_bytes, needs.type_name_size, frame)
        self.checks = [Check(rule, needs) for rule in RULES if rule.amount(needs) is not None]


def fit_check_header(messages):
    """{FIT_CHECK_HEADER: text} for a firmware's message types."""
    needs = FirmwareNeeds(messages)
    return {FIT_CHECK_HEADER: render_template(
        TEMPLATE_DIR, FIT_CHECK_HEADER + '.em', needs=needs, pool_kinds=POOL_KINDS,
        types=[CheckedType(needed) for needed in needs.types],
        library_guard=LIBRARY_HEADER_GUARD, settings_headers=SETTINGS_HEADERS,
        usr_config_header=USR_CONFIG, packet_config_header=PACKET_CONFIG,
        frame_slots=FRAME_SLOTS, frame_size_macro=LIBRARY_PASSES_FRAME_SIZE)}
