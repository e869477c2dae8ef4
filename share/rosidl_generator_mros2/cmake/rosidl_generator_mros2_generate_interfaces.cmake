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
# the listed interfaces. An action, a type mros2 cannot carry (a wchar, a
# long double) and every type that holds one have no mros2 header: the
# program says so in one line each, and the package builds, as with
# rosidl_generator_cpp. So the headers below may be fewer than the
# interfaces: they are installed OPTIONAL, and the program lists those it
# wrote (--header-list) for the ament index marker.
#
# The install layout, one include root per package, so that no two
# interface packages (in a merged install, or two Debian packages) install
# the same file:
#
#   <prefix>/include/<pkg>/mros2/<pkg>/msg/<type>.hpp   the package's mros2
#   <prefix>/include/<pkg>/mros2/<pkg>/srv/<name>.hpp   include root
#   <prefix>/share/ament_index/resource_index/rosidl_generator_mros2__packages/<pkg>
#                                                       the marker: the
#                                                       generator ran (the
#                                                       headers it wrote,
#                                                       one a line)
#
# rosidl_generator_cpp installs <pkg>/msg/<type>.hpp under include/<pkg>
# (Humble on); the mros2 headers have the same relative names (an app's
# #include "pkg/msg/type.hpp" is the same for both), so they need a root of
# their own: include/<pkg>/mros2. The support headers every mros2 header
# includes ("mros2_message_wire.hpp", "mros_message_containers.h") are the
# generator's, installed once with it in
# <generator prefix>/include/rosidl_generator_mros2
# (rosidl_generator_mros2_SUPPORT_INCLUDE_DIR, rosidl_generator_mros2-extras.cmake).
#
# The exported target ${rosidl_generate_interfaces_TARGET}__rosidl_generator_mros2
# carries both include dirs and those of the interface packages it depends
# on. Only what names it gets it: after find_package(<pkg>), as
# <pkg>::<pkg>__rosidl_generator_mros2 or <pkg>_TARGETS__rosidl_generator_mros2
# (as rosidl's typesupport targets are named), and in the package itself
# through rosidl_get_typesupport_target(var <target> rosidl_generator_mros2).
# It is not among <pkg>_TARGETS, which ament_target_dependencies() and
# ${<pkg>_TARGETS} give every target of a consumer: its headers have the
# names of rosidl_generator_cpp's, and would hide them from rclcpp code.

# Every header includes the support headers, which the target below names
# by absolute path: a generator installed without them (an older
# colcon-mros, or the checkout's share/ used as the CMake package) would
# give a target no app can use.
if(NOT IS_DIRECTORY "${rosidl_generator_mros2_SUPPORT_INCLUDE_DIR}")
  message(FATAL_ERROR "rosidl_generator_mros2: no support headers in "
    "${rosidl_generator_mros2_SUPPORT_INCLUDE_DIR}; reinstall colcon-mros (scripts/setup.sh)")
endif()

set(_mros2_output_dir "${CMAKE_CURRENT_BINARY_DIR}/rosidl_generator_mros2")
set(_mros2_stamp "${CMAKE_CURRENT_BINARY_DIR}/rosidl_generator_mros2__${rosidl_generate_interfaces_TARGET}.stamp")
set(_mros2_header_list "${CMAKE_CURRENT_BINARY_DIR}/rosidl_generator_mros2__${rosidl_generate_interfaces_TARGET}.headers")

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

# The headers are the rule's BYPRODUCTS, the stamp its OUTPUT: the program
# leaves an unchanged header as it is (what includes it is not rebuilt for
# nothing), so a header may stay older than the .idl it comes from, which
# is what CMake's BYPRODUCTS are for ("files the command is expected to
# produce but whose modification time may or may not be newer than the
# dependencies"; Ninja restats them, and regenerates a missing one). As
# OUTPUTs, an unchanged header would leave the rule out of date forever
# (make and Ninja compare each output's time), or be touched by make's
# rules for the outputs after the first, rebuilding its includers. The
# stamp is what keeps the rule from running again. The program
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
  BYPRODUCTS ${_mros2_headers} "${_mros2_header_list}"
  COMMAND "${rosidl_generator_mros2_BIN}" --generator-arguments-file "${_mros2_arguments_file}"
    --header-list "${_mros2_header_list}" ${_mros2_depfile_arguments}
  COMMAND "${CMAKE_COMMAND}" -E touch "${_mros2_stamp}"
  DEPENDS ${_mros2_target_dependencies} "${_mros2_arguments_file}"
  ${_mros2_depfile_options}
  COMMENT "Generating mros2 headers for ROS interfaces"
  VERBATIM)
add_custom_target(${rosidl_generate_interfaces_TARGET}__mros2 DEPENDS "${_mros2_stamp}")
add_dependencies(${rosidl_generate_interfaces_TARGET} ${rosidl_generate_interfaces_TARGET}__mros2)

# The target an app links, as rosidl_generator_cpp's
# ${target}__rosidl_generator_cpp: the package's mros2 include root (the
# build tree's, or the install's), the generator's support headers and,
# through the dependency packages' targets, their include roots (a header
# includes those of the types it contains).
set(_mros2_target_suffix "__rosidl_generator_mros2")
set(_mros2_target "${rosidl_generate_interfaces_TARGET}${_mros2_target_suffix}")
add_library(${_mros2_target} INTERFACE)
add_library(${PROJECT_NAME}::${_mros2_target} ALIAS ${_mros2_target})
# The support dir is absolute in both interfaces: it is the generator's
# install, not the package's, and an app of the package needs no
# find_package(rosidl_generator_mros2) for it.
target_include_directories(${_mros2_target} INTERFACE
  "$<BUILD_INTERFACE:${_mros2_output_dir}>"
  "$<INSTALL_INTERFACE:include/${PROJECT_NAME}/mros2>"
  "${rosidl_generator_mros2_SUPPORT_INCLUDE_DIR}")
foreach(_mros2_pkg ${rosidl_generate_interfaces_DEPENDENCY_PACKAGE_NAMES})
  # Empty for a package built without the mros2 generator.
  target_link_libraries(${_mros2_target} INTERFACE ${${_mros2_pkg}_TARGETS${_mros2_target_suffix}})
endforeach()
# A target of the package that links it waits for the headers (CMake takes
# target-level dependencies of an INTERFACE library from 3.19; before, the
# package's target waits for them through the __mros2 target above).
if(NOT CMAKE_VERSION VERSION_LESS 3.19)
  add_dependencies(${_mros2_target} ${rosidl_generate_interfaces_TARGET}__mros2)
  add_dependencies(${rosidl_generate_interfaces_TARGET} ${_mros2_target})
endif()

if(NOT rosidl_generate_interfaces_SKIP_INSTALL)
  # Exactly the listed interfaces' headers (not the output dir, which may
  # keep the header of an interface since removed), per kind; OPTIONAL: a
  # type mros2 cannot carry has none.
  foreach(_mros2_kind msg srv)
    set(_mros2_kind_headers "")
    foreach(_mros2_header ${_mros2_headers})
      get_filename_component(_mros2_header_dir "${_mros2_header}" DIRECTORY)
      get_filename_component(_mros2_header_dir "${_mros2_header_dir}" NAME)
      if(_mros2_header_dir STREQUAL _mros2_kind)
        list(APPEND _mros2_kind_headers "${_mros2_header}")
      endif()
    endforeach()
    if(_mros2_kind_headers)
      install(
        FILES ${_mros2_kind_headers}
        DESTINATION "include/${PROJECT_NAME}/mros2/${PROJECT_NAME}/${_mros2_kind}"
        OPTIONAL)
    endif()
  endforeach()
  # What colcon build --mros-export reads to tell a package the generator
  # did not run for (a package with actions alone has no header and still
  # has the marker): the headers the program wrote.
  install(
    FILES "${_mros2_header_list}"
    DESTINATION "share/ament_index/resource_index/rosidl_generator_mros2__packages"
    RENAME "${PROJECT_NAME}")

  # Exported as ament_export_targets() does, but for <pkg>_TARGETS: an
  # extra of <pkg>Config.cmake includes the export file alone.
  install(TARGETS ${_mros2_target} EXPORT export_${_mros2_target})
  install(
    EXPORT export_${_mros2_target}
    DESTINATION "share/${PROJECT_NAME}/cmake"
    NAMESPACE "${PROJECT_NAME}::"
    FILE "${_mros2_target}Export.cmake")
  set(_mros2_config_extra
    "${CMAKE_CURRENT_BINARY_DIR}/rosidl_generator_mros2_extras/${PROJECT_NAME}-mros2-extras.cmake")
  file(WRITE "${_mros2_config_extra}"
    "# The mros2 headers' target, kept out of ${PROJECT_NAME}_TARGETS (rosidl_generator_mros2).\n"
    "include(\"\${${PROJECT_NAME}_DIR}/${_mros2_target}Export.cmake\")\n")
  list(APPEND ${PROJECT_NAME}_CONFIG_EXTRAS "${_mros2_config_extra}")
  # <pkg>_TARGETS__rosidl_generator_mros2 in an app's scope after
  # find_package(<pkg>), which the loop above reads for dependencies.
  rosidl_export_typesupport_targets(${_mros2_target_suffix} ${_mros2_target})
endif()
