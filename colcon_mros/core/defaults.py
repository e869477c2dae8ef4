# SPDX-License-Identifier: BSD-3-Clause
"""The choices and defaults the command line offers.

Kept free of ROS imports, so that ``genmros --help`` and the error for a
missing genmsg need nothing of ROS.
"""

# What an export writes: everything, or one of its two halves (an export
# dir shared by many firmwares takes the headers, each firmware its aggregates).
EXPORT_PARTS = ('all', 'headers', 'aggregates')

# How strings and variable arrays are stored (colcon_mros.core.storage);
# the first is the default.
STORAGE_KINDS = ('heap', 'bounded')
DEFAULT_STORAGE = STORAGE_KINDS[0]

# Which definition text the headers carry (colcon_mros.ros1.identity): gencpp's,
# or the same declarations without comments, for a firmware's flash; the
# first is the default.
DEFINITION_TEXTS = ('full', 'compact')
DEFAULT_DEFINITION_TEXT = DEFINITION_TEXTS[0]
