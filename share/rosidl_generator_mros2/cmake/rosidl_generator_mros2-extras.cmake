# The mros2 generator's registration with rosidl and the genmros it runs.

# rosidl_generate_interfaces() runs the extensions registered for
# "rosidl_generate_idl_interfaces" in the order they were registered,
# including "${<package>_DIR}/<file>" in its own scope (ament_execute_extensions).
find_package(ament_cmake_core QUIET REQUIRED)
# What defines rosidl_generate_interfaces() (as rosidl_generator_cpp
# exports it), so a package needs only this find_package() on Debian 12.
find_package(rosidl_cmake QUIET REQUIRED)
ament_register_extension(
  "rosidl_generate_idl_interfaces"
  "rosidl_generator_mros2"
  "rosidl_generator_mros2_generate_interfaces.cmake")

# genmros: the one installed with this file (<prefix>/bin), else on PATH;
# -DGENMROS_BIN=... names another one (a checkout's wrapper, a venv's).
find_program(GENMROS_BIN genmros
  HINTS "${rosidl_generator_mros2_IMPORT_PREFIX}/bin"
  DOC "genmros, the message generator of colcon-mros (runs 'genmros mros2-generate')")
if(NOT GENMROS_BIN)
  message(FATAL_ERROR "rosidl_generator_mros2: genmros not found; install colcon-mros "
    "(scripts/setup.sh) or set GENMROS_BIN")
endif()
