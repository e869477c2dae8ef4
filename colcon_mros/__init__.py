"""colcon-mros: ROS 1 message headers for mROS firmware, from the ROS build.

The package is laid out along the generation pipeline:

- ``parse``: load .msg/.srv files through genmsg (errors carry file and line)
- ``model``: turn genmsg specs into a C++ type model, with ``names`` (C++
  spellings of ROS names), ``identity`` (MD5 sums, definition texts) and
  ``storage`` (heap or bounded strings and arrays, options files)
- ``render``: fill the empy templates in ``templates/`` from the model
- ``output``: write generated files atomically
- ``workspace``: find packages and their message directories
- ``generate``: generator mode, one .msg/.srv file (what catkin runs)
- ``export``: the whole-workspace export used by firmware builds
- ``cli``: the ``genmros`` command, with ``defaults`` (its choices),
  ``ros_environment`` (genmsg and empy present?) and ``installed_files``
  (where the CMake module and make fragment are)
- ``colcon_export``: ``colcon build --mros-export``
"""

__version__ = '0.1.0'
