# SPDX-License-Identifier: BSD-3-Clause
"""The mros2 back end: C++ message headers for mros2 (mROS 2, ROS 2 on MCUs).

:mod:`colcon_mros.mros2.cpp` spells the ROS 2 type model
(:mod:`colcon_mros.ros2.model`) in C++; the logic-free templates in
``templates/`` render it; ``support/mros2_message_wire.hpp``, a static
header, holds the CDR code every message uses; :mod:`colcon_mros.mros2.render`
puts them together, and :mod:`colcon_mros.export.mros2_export` writes what one
firmware needs, templates.hpp included.
"""
