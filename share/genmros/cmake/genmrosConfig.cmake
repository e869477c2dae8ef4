# SPDX-License-Identifier: BSD-3-Clause
# find_package(genmros): the catkin message generator (genmros-extras.cmake)
# and the firmware-side functions mros_import_messages() and
# mros_generate_messages() (mros_generate.cmake).
#
# Installed under <prefix>/share/genmros/cmake by the colcon-mros Python
# distribution; genmsg finds it through the marker /etc/ros/genmsg/genmros.

if(genmros_CONFIG_INCLUDED)
  return()
endif()
set(genmros_CONFIG_INCLUDED TRUE)

set(genmros_FOUND TRUE)
set(genmros_INCLUDE_DIRS "")
set(genmros_LIBRARIES "")

# mros_generate.cmake first: it finds GENMROS_BIN, which the generator runs.
include("${CMAKE_CURRENT_LIST_DIR}/mros_generate.cmake")
include("${CMAKE_CURRENT_LIST_DIR}/mros2_generate.cmake")
include("${CMAKE_CURRENT_LIST_DIR}/genmros-extras.cmake")
