# The mros2 generator's part of rosidl_generate_interfaces(): included by
# ament_execute_extensions("rosidl_generate_idl_interfaces") in the scope of
# the package's CMakeLists.txt, with rosidl_generate_interfaces_TARGET,
# rosidl_generate_interfaces_IDL_TUPLES (<base>:<kind>/<Type>.idl, the .idl
# forms rosidl_adapter made), rosidl_generate_interfaces_ABS_IDL_FILES,
# rosidl_generate_interfaces_DEPENDENCY_PACKAGE_NAMES (the interface
# packages it depends on, found by find_package()) and
# rosidl_generate_interfaces_SKIP_INSTALL set.
#
# genmros mros2-generate reads the package's own msg/ and srv/ files (a
# .msg or .srv over rosidl's .idl of it, so its errors name the file the
# user wrote) and finds the types it contains from other packages in their
# install prefixes; it writes <output>/<pkg>/msg/<type>.hpp and
# <output>/<pkg>/srv/<service>.hpp, installed to <prefix>/include/mros2/.

set(_mros2_output_dir "${CMAKE_CURRENT_BINARY_DIR}/rosidl_generator_mros2")
set(_mros2_stamp "${CMAKE_CURRENT_BINARY_DIR}/rosidl_generator_mros2__${rosidl_generate_interfaces_TARGET}.stamp")

# The headers, one per interface: rosidl's own name rule (Type -> type.hpp).
set(_mros2_headers "")
foreach(_mros2_idl_file ${rosidl_generate_interfaces_ABS_IDL_FILES})
  get_filename_component(_mros2_kind "${_mros2_idl_file}" DIRECTORY)
  get_filename_component(_mros2_kind "${_mros2_kind}" NAME)
  get_filename_component(_mros2_name "${_mros2_idl_file}" NAME_WE)
  string_camel_case_to_lower_case_underscore("${_mros2_name}" _mros2_header)
  list(APPEND _mros2_headers "${_mros2_output_dir}/${PROJECT_NAME}/${_mros2_kind}/${_mros2_header}.hpp")
endforeach()

# Inputs: the files the package's interfaces are written in (the .idl forms
# change after a .msg changes, when CMake reruns rosidl_adapter), its
# manifest, and the interface files of the packages it depends on.
file(GLOB _mros2_sources CONFIGURE_DEPENDS
  "${CMAKE_CURRENT_SOURCE_DIR}/msg/*.msg" "${CMAKE_CURRENT_SOURCE_DIR}/msg/*.idl"
  "${CMAKE_CURRENT_SOURCE_DIR}/srv/*.srv" "${CMAKE_CURRENT_SOURCE_DIR}/srv/*.idl")
set(_mros2_depends
  ${_mros2_sources}
  ${rosidl_generate_interfaces_ABS_IDL_FILES}
  "${CMAKE_CURRENT_SOURCE_DIR}/package.xml")

# Where the packages it depends on are: the prefix each was found in first
# (<prefix>/share/<pkg>/cmake), then AMENT_PREFIX_PATH and CMAKE_PREFIX_PATH
# as colcon set them when it configured this package (with none, genmros
# takes AMENT_PREFIX_PATH when it runs).
set(_mros2_prefixes "")
foreach(_mros2_pkg ${rosidl_generate_interfaces_DEPENDENCY_PACKAGE_NAMES})
  get_filename_component(_mros2_prefix "${${_mros2_pkg}_DIR}/../../.." ABSOLUTE)
  list(APPEND _mros2_prefixes "${_mros2_prefix}")
  foreach(_mros2_file ${${_mros2_pkg}_IDL_FILES} ${${_mros2_pkg}_INTERFACE_FILES})
    get_filename_component(_mros2_file "${${_mros2_pkg}_DIR}/../${_mros2_file}" ABSOLUTE)
    if(EXISTS "${_mros2_file}")
      list(APPEND _mros2_depends "${_mros2_file}")
    endif()
  endforeach()
endforeach()
string(REPLACE ":" ";" _mros2_env_prefixes "$ENV{AMENT_PREFIX_PATH}")
list(APPEND _mros2_prefixes ${_mros2_env_prefixes} ${CMAKE_PREFIX_PATH})
string(REPLACE ":" ";" _mros2_env_prefixes "$ENV{CMAKE_PREFIX_PATH}")
list(APPEND _mros2_prefixes ${_mros2_env_prefixes})
if(_mros2_prefixes)
  list(REMOVE_DUPLICATES _mros2_prefixes)
endif()
set(_mros2_prefix_args "")
foreach(_mros2_prefix ${_mros2_prefixes})
  if(IS_DIRECTORY "${_mros2_prefix}")
    list(APPEND _mros2_prefix_args --prefix "${_mros2_prefix}")
  endif()
endforeach()
# genmros leaves unchanged headers as they are (what includes them is not
# rebuilt for nothing); the stamp marks the rule as done.
add_custom_command(
  OUTPUT "${_mros2_stamp}"
  BYPRODUCTS ${_mros2_headers}
  COMMAND "${GENMROS_BIN}" mros2-generate
    --package-dir "${CMAKE_CURRENT_SOURCE_DIR}"
    -o "${_mros2_output_dir}"
    ${_mros2_prefix_args}
  COMMAND "${CMAKE_COMMAND}" -E touch "${_mros2_stamp}"
  DEPENDS "${GENMROS_BIN}" ${_mros2_depends}
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
