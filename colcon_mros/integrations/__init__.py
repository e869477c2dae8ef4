"""The build integrations: where catkin and colcon run the generator.

- catkin_generator: generator mode, what genmsg runs per package
  (share/genmros/cmake/genmros-extras.cmake calls it)
- catkin_export_dir: what catkin's configure step asks with MROS_EXPORT_DIR
- colcon_argument_parser: the colcon_core.argument_parser extension point
  (``colcon build --mros-export DIR``)
- colcon_export: what that export holds, once colcon has built
- installed_files: where the CMake module (cmake/mros_generate.cmake) and
  the make fragment (cmake/genmros.mk) are, in a checkout or an install
- cmake_names: the names those CMake files take from genmros
  (cmake/genmros-names.cmake)

Imports the export and generator layers and colcon_mros.errors.
"""
