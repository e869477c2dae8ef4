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
