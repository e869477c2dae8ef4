# SPDX-License-Identifier: BSD-3-Clause
"""The mROS v1 choices the command line offers, free of ROS imports like
:mod:`colcon_mros.core.defaults`."""

# PUB_MSG_MAX_SIZE share of a type without a maximum wire size.
DEFAULT_VARIABLE_SIZE_BUDGET = 1024

# genmros mros-v1-pc: 32-bit ARM Linux (the board's instruction set) or this PC.
PC_TARGETS = ('arm', 'native')
