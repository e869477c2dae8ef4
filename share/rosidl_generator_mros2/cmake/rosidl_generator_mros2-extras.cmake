# SPDX-License-Identifier: BSD-3-Clause
# The mros2 generator's registration with rosidl and the program it runs.

# rosidl_generate_interfaces() runs the extensions registered for
# "rosidl_generate_idl_interfaces" in the order they were registered,
# including "${<package>_DIR}/<file>" in its own scope (ament_execute_extensions).
find_package(ament_cmake_core QUIET REQUIRED)
# What defines rosidl_generate_interfaces() and rosidl_write_generator_arguments()
# (as rosidl_generator_cpp exports it), so a package needs only this
# find_package() on Debian 12.
find_package(rosidl_cmake QUIET REQUIRED)
ament_register_extension(
  "rosidl_generate_idl_interfaces"
  "rosidl_generator_mros2"
  "rosidl_generator_mros2_generate_interfaces.cmake")

# The generator: the rosidl_generator_mros2 installed with this file
# (<prefix>/bin), else on PATH; -Drosidl_generator_mros2_BIN=... names
# another one (a checkout's wrapper, a venv's).
find_program(rosidl_generator_mros2_BIN rosidl_generator_mros2
  HINTS "${rosidl_generator_mros2_IMPORT_PREFIX}/bin"
  DOC "the mros2 generator of colcon-mros, run over rosidl's generator arguments file")
if(NOT rosidl_generator_mros2_BIN)
  message(FATAL_ERROR "rosidl_generator_mros2: its program was not found; install colcon-mros "
    "(scripts/setup.sh) or set rosidl_generator_mros2_BIN")
endif()

# The static headers every mros2 header includes (mros2_message_wire.hpp,
# mros_message_containers.h), installed once with the generator, not with
# each interface package (colcon-mros' setup.cfg puts them in
# <prefix>/include/rosidl_generator_mros2). Each package's exported target
# names this directory; an app that reads mros2 headers some other way
# links rosidl_generator_mros2::support.
set(rosidl_generator_mros2_SUPPORT_INCLUDE_DIR
  "${rosidl_generator_mros2_IMPORT_PREFIX}/include/rosidl_generator_mros2")
if(NOT TARGET rosidl_generator_mros2::support
    AND EXISTS "${rosidl_generator_mros2_SUPPORT_INCLUDE_DIR}")
  add_library(rosidl_generator_mros2::support INTERFACE IMPORTED)
  set_target_properties(rosidl_generator_mros2::support PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${rosidl_generator_mros2_SUPPORT_INCLUDE_DIR}")
endif()
