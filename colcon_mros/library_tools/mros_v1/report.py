# SPDX-License-Identifier: BSD-3-Clause
"""``genmros mros-v1-fit``: an app's message types against its mROS v1
library's settings, one table row per type.

The Fit comes from :mod:`.fit_flow` (an app's, or an export dir's).
Each row shows what the type needs (definition
text, the connection headers ROS nodes send, the largest frame) and, for
each setting, ``ok`` or the value it needs; then the library's tables beside
the number of types, and the lines a build would stop with.
"""

from colcon_mros.mros_v1.rules import PEER_NAME_MAX


def _cell(requirement):
    if requirement.needed is None:
        return 'unknown'
    if not requirement.fits:  # the value the error line asks for
        return 'needs %d' % (requirement.assumed or requirement.needed)
    if requirement.names_budget is not None:
        return 'names <= %d' % requirement.names_budget
    return 'ok'


def report(fit, settings_files):
    """The report of a Fit to the settings_files: its text, and whether a
    build would stop."""
    lines = ['Settings: %s' % ', '.join(settings_files),
             "Connection headers: their bytes besides the topic and the ROS peer's caller id. "
             "'names <= N': fits while the two take at most N bytes together (with a topic of "
             'up to %d, %s, and a caller id of up to %d it does not).'
             % (fit.topic_name_max.value, fit.topic_name_max.name, PEER_NAME_MAX), '']
    rows = []
    for needed, requirements in fit.type_requirements:
        frame = 'no maximum' if needed.max_frame is None else str(needed.max_frame)
        rows.append([needed.full_name, str(needed.text_bytes), str(needed.subscriber_header),
                     str(needed.publisher_header), frame] + [_cell(r) for r in requirements])
    header = ['type', 'definition text', 'subscriber header', 'publisher header',
              'largest frame'] + ['%s %d' % (s.name, s.value) for s in fit.rule_settings]
    lines.append('| %s |' % ' | '.join(header))
    lines.append('|---|' + '---:|' * (len(header) - 1))
    lines += ['| %s |' % ' | '.join(row) for row in rows]
    lines.append('')
    lines.append('Tables (each type takes a topic per topic name, each ROS peer a connector): '
                 '%s; this firmware has %d type%s.'
                 % (', '.join('%s %d' % (s.name, s.value) for s in fit.table_sizes()),
                    len(fit.needs.types), '' if len(fit.needs.types) == 1 else 's'))
    problems = [misfit.line() for misfit in fit.misfits]
    lines.append('')
    lines += ['error: %s' % line for line in problems] or ['Every type fits.']
    lines += ['warning: %s' % line for line in fit.warnings]
    return '\n'.join(lines) + '\n', bool(problems)
