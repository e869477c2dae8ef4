# SPDX-License-Identifier: BSD-3-Clause
"""Exports: the headers one firmware needs (``genmros mros-v1-export``,
``genmros mros2-export``), and the export dir catkin and colcon fill, with
the run record that says when an export is up to date.

Uses the back ends (and through them the front ends and the core);
docs/design.md maps the modules and layers.
"""
