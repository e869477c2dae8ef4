"""Exports: the headers one firmware needs (``genmros export``), and the
export dir catkin and colcon fill, with the run record that says when an
export is up to date.

Uses the generator and the mROS v1 library's rules (its fit check and
compile-time check); docs/design.md maps the modules and layers.
"""
