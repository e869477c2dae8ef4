# SPDX-License-Identifier: BSD-3-Clause
# The mros2 generator's part of rosidl_generate_interfaces(): included by
# ament_execute_extensions("rosidl_generate_idl_interfaces") in the scope of
# the package's CMakeLists.txt, with rosidl_generate_interfaces_TARGET,
# rosidl_generate_interfaces_IDL_TUPLES (<base>:<kind>/<Type>.idl: the .idl
# files given and the forms rosidl_adapter made of the .msg and .srv files),
# rosidl_generate_interfaces_ABS_IDL_FILES,
# rosidl_generate_interfaces_DEPENDENCY_PACKAGE_NAMES (the interface
# packages it depends on, found by find_package()) and
# rosidl_generate_interfaces_SKIP_INSTALL set, as for rosidl_generator_cpp.
#
# As rosidl_generator_cpp does, it writes the generator arguments file
# (rosidl_write_generator_arguments(), the same keywords on rosidl 3.1
# (Humble), 3.3 and 4.x) and runs its program over it, which writes
# <output>/<pkg>/msg/<type>.hpp and <output>/<pkg>/srv/<service>.hpp for
# exactly the listed interfaces, installed to <prefix>/include/mros2/. An
# action has no mros2 header: the program says so in one line.

set(_mros2_output_dir "${CMAKE_CURRENT_BINARY_DIR}/rosidl_generator_mros2")
set(_mros2_stamp "${CMAKE_CURRENT_BINARY_DIR}/rosidl_generator_mros2__${rosidl_generate_interfaces_TARGET}.stamp")

# The headers, one per message and service: rosidl's own name rule (Type -> type.hpp).
set(_mros2_headers "")
foreach(_mros2_idl_file ${rosidl_generate_interfaces_ABS_IDL_FILES})
  get_filename_component(_mros2_kind "${_mros2_idl_file}" DIRECTORY)
  get_filename_component(_mros2_kind "${_mros2_kind}" NAME)
  if(_mros2_kind STREQUAL "msg" OR _mros2_kind STREQUAL "srv")
    get_filename_component(_mros2_name "${_mros2_idl_file}" NAME_WE)
    string_camel_case_to_lower_case_underscore("${_mros2_name}" _mros2_header)
    list(APPEND _mros2_headers "${_mros2_output_dir}/${PROJECT_NAME}/${_mros2_kind}/${_mros2_header}.hpp")
  endif()
endforeach()

# The .idl files of the packages it depends on, as <pkg>:<path> (rosidl
# 4.x finds them with rosidl_find_package_idl(); 3.x below <pkg>_DIR).
set(_mros2_dependencies "")
set(_mros2_dependency_files "")
foreach(_mros2_pkg ${rosidl_generate_interfaces_DEPENDENCY_PACKAGE_NAMES})
  foreach(_mros2_idl ${${_mros2_pkg}_IDL_FILES})
    if(COMMAND rosidl_find_package_idl)
      rosidl_find_package_idl(_mros2_file "${_mros2_pkg}" "${_mros2_idl}")
    else()
      get_filename_component(_mros2_file "${${_mros2_pkg}_DIR}/../${_mros2_idl}" ABSOLUTE)
    endif()
    list(APPEND _mros2_dependencies "${_mros2_pkg}:${_mros2_file}")
    list(APPEND _mros2_dependency_files "${_mros2_file}")
  endforeach()
endforeach()

# The .msg and .srv files the user wrote (the target's sources), so that
# genmros' own errors name them rather than rosidl_adapter's .idl forms.
get_target_property(_mros2_interface_files ${rosidl_generate_interfaces_TARGET} SOURCES)
if(NOT _mros2_interface_files)
  set(_mros2_interface_files "")
endif()

set(_mros2_target_dependencies
  "${rosidl_generator_mros2_BIN}"
  ${rosidl_generate_interfaces_ABS_IDL_FILES}
  ${_mros2_dependency_files})

set(_mros2_arguments_file "${CMAKE_CURRENT_BINARY_DIR}/rosidl_generator_mros2__arguments.json")
rosidl_write_generator_arguments(
  "${_mros2_arguments_file}"
  PACKAGE_NAME "${PROJECT_NAME}"
  IDL_TUPLES "${rosidl_generate_interfaces_IDL_TUPLES}"
  ROS_INTERFACE_FILES "${_mros2_interface_files}"
  ROS_INTERFACE_DEPENDENCIES "${_mros2_dependencies}"
  OUTPUT_DIR "${_mros2_output_dir}"
  TARGET_DEPENDENCIES ${_mros2_target_dependencies})

# The program leaves unchanged headers as they are (what includes them is
# not rebuilt for nothing); the stamp marks the rule as done. The program
# also writes a depfile naming its own files (code, templates, static
# headers, as rosidl_generator_cpp's GENERATOR_FILES), so a new genmros
# regenerates the headers without a program run at configure time (CMake
# takes a DEPFILE with Makefiles from 3.20; an older one depends on the
# program alone).
set(_mros2_depfile "${_mros2_stamp}.d")
if(CMAKE_VERSION VERSION_LESS 3.20)
  set(_mros2_depfile_options "")
  set(_mros2_depfile_arguments "")
else()
  set(_mros2_depfile_options DEPFILE "${_mros2_depfile}")
  set(_mros2_depfile_arguments
    --dependency-file "${_mros2_depfile}" --dependency-target "${_mros2_stamp}")
endif()
add_custom_command(
  OUTPUT "${_mros2_stamp}"
  BYPRODUCTS ${_mros2_headers}
  COMMAND "${rosidl_generator_mros2_BIN}" --generator-arguments-file "${_mros2_arguments_file}"
    ${_mros2_depfile_arguments}
  COMMAND "${CMAKE_COMMAND}" -E touch "${_mros2_stamp}"
  DEPENDS ${_mros2_target_dependencies} "${_mros2_arguments_file}"
  ${_mros2_depfile_options}
  COMMENT "Generating mros2 headers for ROS interfaces"
  VERBATIM)
add_custom_target(${rosidl_generate_interfaces_TARGET}__mros2 DEPENDS "${_mros2_stamp}")
add_dependencies(${rosidl_generate_interfaces_TARGET} ${rosidl_generate_interfaces_TARGET}__mros2)

if(NOT rosidl_generate_interfaces_SKIP_INSTALL)
  # <prefix>/include/mros2/<pkg>/msg/<type>.hpp: one include root for every
  # package's mros2 headers, beside rosidl's include/<pkg>/<pkg>/...
  install(
    DIRECTORY "${_mros2_output_dir}/"
    DESTINATION "include/mros2"
    FILES_MATCHING PATTERN "*.hpp" PATTERN "*.h")
endif()
