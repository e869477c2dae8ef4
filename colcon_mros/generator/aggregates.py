"""The per-firmware aggregates' data: what msg_max_size.h reports.

The mROS v1 library sizes its publish buffer with ``PUB_MSG_MAX_SIZE``; a
firmware's ``msg_max_size.h`` sets it to the largest wire image of the
firmware's types, and says for each how it was found (exact, at most, or no
maximum and which field has none).
"""

from colcon_mros.generator.defaults import DEFAULT_VARIABLE_SIZE_BUDGET


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
