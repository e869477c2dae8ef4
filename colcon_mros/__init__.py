"""colcon-mros: ROS 1 message headers for mROS firmware, from the ROS build.

One subpackage per product, each importing only the layers below it
(tests/test_layers.py holds it to that):

- ``cli``: the ``genmros`` command, thin argparse subcommands (top)
- ``targets``: where mROS apps run off the board (``targets.mros_v1_pc``:
  the user's mROS v1 library and app on a PC, ``genmros mros-v1-pc``)
- ``integrations``: catkin's generator mode and export dir, the colcon
  extension, where the CMake module and the make fragment are
- ``export``: the export of one firmware's types, and the export dir
- ``generator``: parse -> model -> C++ view -> templates
- ``errors``: the one exception type users see (bottom)
"""

__version__ = '0.1.0'
