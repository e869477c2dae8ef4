# SPDX-License-Identifier: BSD-3-Clause
# find_package(genmros) through the catkin prefix (genmros catkin-prefix):
# with that prefix on CMAKE_PREFIX_PATH, CMake finds genmros here even when
# the install's bin/ is not on PATH (pip --user before the next login), and
# this file hands over to the install's genmrosConfig.cmake.
# Installed as <prefix>/share/genmros/catkin_prefix/share/genmros/cmake/.
include("${CMAKE_CURRENT_LIST_DIR}/../../../../cmake/genmrosConfig.cmake")
