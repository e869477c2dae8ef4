# SPDX-License-Identifier: BSD-3-Clause
"""The fit check: a firmware's message types against its mROS v1 library's settings.

Each :data:`.rules.RULES` entry is checked for each type against the
settings (:mod:`colcon_mros.core.settings`). A setting too small for a type
is a :class:`Misfit`: one line naming the type, the setting, the file and line
that set it, its value and the value needed. A connection header that fits
only while the names are short, and a type without a largest frame (a
string or variable array in heap storage), which only might not fit a
memory pool, are warnings; :meth:`Fit.refuse` is the one place either
becomes an error. The firmware as a whole is checked against
:data:`.rules.FRAME_SLOTS` where the library passes delivery no frame size.
"""

from colcon_mros.core.settings import misfit_line
from colcon_mros.errors import GenmrosError, GenmrosProblems
from colcon_mros.mros_v1.rules import (FRAME_SLOTS, PEER_NAME_MAX, RULES, TABLES,
                                       TOPIC_NAME_MAX, FirmwareNeeds)


class Misfit:
    """A setting too small for a type: the build's one line. asked is the
    value the line asks for; for a connection header, which counts with the
    longest names the settings allow, with_shortest_names is what it needs
    even with the shortest (None for the other rules)."""

    def __init__(self, type_name, what, setting, asked, with_shortest_names=None):
        self.type_name = type_name
        self.what = what
        self.setting = setting
        self.asked = asked
        self.with_shortest_names = with_shortest_names

    def line(self):
        """FILE:LINE of the setting, then the type, what needs it, the value
        it needs and the value it has."""
        shortest = ('' if self.with_shortest_names is None
                    else '; even with the shortest topic and caller id it needs %d'
                    % self.with_shortest_names)
        return misfit_line(self.setting, self.type_name, self.what, self.asked, shortest)


class FrameSlotsMisfit:
    """More blocks in the publishing pools than on-board delivery has slots
    for (:data:`.rules.FRAME_SLOTS`): the build's one line."""

    def __init__(self, blocks, block_settings, slots):
        self.blocks = blocks
        self.block_settings = block_settings
        self.slots = slots  # a Setting, or None: the default

    def line(self):
        """FILE:LINE of the slots' setting (else of the pools'), the blocks,
        the value needed and the value it has."""
        where = (self.slots or self.block_settings[-1]).where()
        value = ('it is %d' % self.slots.value if self.slots else
                 "it is not defined: mros_v1_delivery.h's default is %d" % FRAME_SLOTS.default)
        return ('%s: the publishing pools hold %d blocks (%s), each of which can hold a frame '
                'waiting for on-board delivery: %s needs >= %d in every file (%s), or the library '
                "passes the frame's size (genmros' patch set)"
                % (where, self.blocks, ', '.join('%s %d' % (setting.name, setting.value)
                                                 for setting in self.block_settings[1:]),
                   FRAME_SLOTS.setting, self.blocks, value))


def _required(settings, name):
    if name not in settings:
        raise GenmrosError('the mROS v1 settings given define no %s (give the library\'s '
                           'mros_packet_config.h and the app\'s mros_usr_config.h)' % name)
    return settings[name]


def largest_pool(settings, kind):
    """The Setting of the largest memory pool block of one PoolKind."""
    count = _required(settings, kind.count).value
    pools = [settings[name] for name in kind.sizes[:count] if name in settings]
    if not pools:
        raise GenmrosError('the mROS v1 settings given define none of %s' % ', '.join(
            kind.sizes[:max(count, 1)]))
    return max(pools, key=lambda pool: pool.value)


class Requirement:
    """What one type needs of one setting: needed bytes for certain (None
    where there is no largest size: a frame in heap storage); a connection
    header also names_free, its bytes besides the names (topic and caller
    id), and assumed, its bytes with the longest names counted with."""

    def __init__(self, what, setting, needed, names_free=None, assumed=None):
        self.what = what
        self.setting = setting
        self.needed = needed
        self.names_free = names_free
        self.assumed = assumed

    @property
    def fits(self):
        return self.needed is not None and self.setting.value >= self.needed

    @property
    def names_budget(self):
        """For a header that fits only with short names: the bytes the topic
        and the peer's caller id may take together; else None."""
        if self.assumed is None or not self.fits or self.setting.value >= self.assumed:
            return None
        return self.setting.value - self.names_free


class Fit:
    """A firmware's message types (the ROS 1 front end's models) against settings
    ({name: Setting}): the misfits (errors) and the warnings, and each
    type's requirements (type_requirements: (TypeNeeds, [Requirement]) in
    the types' order, one Requirement per rule and rule_settings' setting).
    frame_table: whether delivery keeps its table of frames published on the
    board (the library passes no frame size: True; it does: False; not
    known, a misfit of the table is a warning: None)."""

    def __init__(self, messages, settings, frame_table=None):
        self.needs = FirmwareNeeds(messages)
        self.settings = settings
        self.topic_name_max = _required(settings, TOPIC_NAME_MAX)
        self.longest_names = self.topic_name_max.value + PEER_NAME_MAX
        self.rule_settings = [largest_pool(settings, rule.setting) if rule.is_pool
                              else _required(settings, rule.setting) for rule in RULES]
        self.type_requirements = [(needed, self._requirements(needed))
                                  for needed in self.needs.types]
        self.misfits = []
        self.warnings = []
        for needed, requirements in self.type_requirements:
            self.misfits += [Misfit(needed.full_name, r.what, r.setting,
                                    asked=r.assumed, with_shortest_names=r.needed)
                             if r.assumed is not None else
                             Misfit(needed.full_name, r.what, r.setting, asked=r.needed)
                             for r in requirements if r.needed is not None and not r.fits]
            self.warnings += [
                '%s: %s needs %s >= %d; %s sets %d, which holds it only while the topic and the '
                "peer's caller id take at most %d bytes together"
                % (needed.full_name, r.what, r.setting.name, r.assumed, r.setting.where(),
                   r.setting.value, r.names_budget)
                for r in requirements if r.names_budget is not None]
            if needed.pool_block is None:
                pools = [(rule.setting.use, setting)
                         for rule, setting in zip(RULES, self.rule_settings) if rule.is_pool]
                self.warnings.append(
                    '%s: no largest frame (%s has no bound): a frame may be larger than the '
                    'largest memory pool block (%s); bounded storage gives the exact need'
                    % (needed.full_name, needed.unbounded_reason,
                       ', '.join('%s: %s = %d at %s' % (use, pool.name, pool.value, pool.where())
                                 for use, pool in pools)))

        blocks, block_settings = FRAME_SLOTS.blocks(settings)
        slots = FRAME_SLOTS.slots(settings)
        if frame_table is not False and blocks > (slots.value if slots else FRAME_SLOTS.default):
            misfit = FrameSlotsMisfit(blocks, block_settings, slots)
            if frame_table:
                self.misfits.append(misfit)
            else:
                self.warnings.append(misfit.line() + ' (whether this library does, is not known '
                                     'here)')

    def _requirements(self, needed):
        """The Requirements of one TypeNeeds, one per rule."""
        requirements = []
        for rule, setting in zip(RULES, self.rule_settings):
            what = rule.describe(needed, self.topic_name_max.value)
            amount = rule.amount(needed)
            if rule.with_names:
                requirements.append(Requirement(what, setting, rule.certain(needed), amount,
                                                amount + self.longest_names))
            else:
                requirements.append(Requirement(what, setting, rule.certain(needed)))
        return requirements

    def refuse(self, strict=False):
        """Raise the misfits (and with strict, the warnings too) as one error
        line each."""
        problems = [misfit.line() for misfit in self.misfits] + (self.warnings if strict else [])
        if problems:
            raise GenmrosProblems(problems)

    def table_sizes(self):
        """The Settings of the library's tables this firmware's topics take room in."""
        return [self.settings[name] for name in TABLES if name in self.settings]
