# SPDX-License-Identifier: BSD-3-Clause
# find_package(rosidl_generator_mros2): registers the mros2 generator with
# rosidl, so that rosidl_generate_interfaces() called after it also writes
# each interface's mros2 header (rosidl_generator_mros2-extras.cmake).
#
# Installed under <prefix>/share/rosidl_generator_mros2/cmake by the
# colcon-mros Python distribution, with the ament index markers
# <prefix>/share/ament_index/resource_index/{packages,rosidl_generator_packages}/rosidl_generator_mros2.
#
# On Debian 12 (no rosidl_default_generators) a package finds it by name
# before calling rosidl_generate_interfaces(). On ROS 2 Humble,
# rosidl_default_generators' extras file lists the rosidl_generator_packages
# resources of the ament index (ament_index_get_resources(), which searches
# AMENT_PREFIX_PATH) and find_package()s each of them QUIET, so
# find_package(rosidl_default_generators) picks this generator up when its
# prefix is on AMENT_PREFIX_PATH (Iron and later do the same in
# rosidl_core_generators); find_package(rosidl_generator_mros2 REQUIRED)
# works on every distribution.

# Found once per directory scope: the extension must not run twice.
if(_rosidl_generator_mros2_CONFIG_INCLUDED)
  return()
endif()
set(_rosidl_generator_mros2_CONFIG_INCLUDED TRUE)

set(rosidl_generator_mros2_FOUND TRUE)
set(rosidl_generator_mros2_FOUND_AMENT_PACKAGE TRUE)
# ament_execute_extensions() includes the extension file from here.
set(rosidl_generator_mros2_DIR "${CMAKE_CURRENT_LIST_DIR}")
# The install prefix (<prefix>/share/rosidl_generator_mros2/cmake/../../..).
get_filename_component(rosidl_generator_mros2_IMPORT_PREFIX "${CMAKE_CURRENT_LIST_DIR}/../../.."
  ABSOLUTE)

include("${CMAKE_CURRENT_LIST_DIR}/rosidl_generator_mros2-extras.cmake")
