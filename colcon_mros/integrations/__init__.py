"""The build integrations: where catkin and colcon run the generator, and
where the CMake module and the make fragment they and a firmware use are.

Uses the export and the generator; docs/design.md maps the modules and layers.
"""
