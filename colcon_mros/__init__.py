"""colcon-mros: ROS 1 message headers for mROS firmware, from the ROS build.

The package is laid out along the generation pipeline:

- ``definition``: a .msg/.srv file, the types it gives and its key
- ``parse``: load .msg/.srv files through genmsg (errors carry file and
  line), with ``names`` (what C++ can take) and ``floats`` (float ranges)
- ``model``: the structure of the types, with ``identity`` (MD5 sums,
  definition texts) and ``storage`` (heap or bounded strings and arrays,
  options files)
- ``cpp``: the model's C++ names (types, containers, literals, guards)
- ``render``: fill the empy templates in ``templates/`` from the C++ names,
  with ``aggregates`` (msg_max_size.h's report)
- ``output``: write generated files atomically
- ``workspace``: find packages and their message directories
- ``generate``: generator mode, a package's .msg/.srv files (what catkin runs)
- ``export``: the export of a firmware's types (``ExportRequest``)
- ``export_dir``: the export dir of catkin and colcon, its only owner
- ``catkin_export``: what catkin's configure step asks with MROS_EXPORT_DIR
- ``cli``: the ``genmros`` command, with ``defaults`` (its choices),
  ``ros_environment`` (genmsg and empy present?) and ``installed_files``
  (where the CMake module and make fragment are)
- ``colcon_export``: the ``colcon build --mros-export`` hook, and
  ``colcon_build``: what it exports
- ``targets.mros_v1_pc``: the user's mROS v1 library and app on a PC
  (``genmros mros-v1-pc``)
"""

__version__ = '0.1.0'
