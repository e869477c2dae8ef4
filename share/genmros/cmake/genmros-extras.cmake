# SPDX-License-Identifier: BSD-3-Clause
# genmros as a genmsg message generator, beside gencpp and genpy.
#
# genmsg's generate_messages() calls the three macros below for every package
# (the language name is "mros": genmsg strips the "gen" of "genmros"):
#   _generate_msg_mros / _generate_srv_mros  once per .msg/.srv: noted here
#   _generate_module_mros                    once per package, after them
# The last adds one custom command for the whole package: one genmros
# process generates every header the package has, after a change only those
# of the files whose definitions changed, and removes those of definitions
# the package no longer has. No genmros process runs per package at
# configure time. The headers go to
# ${CATKIN_DEVEL_PREFIX}/${genmros_INSTALL_DIR}/<pkg>/<Type>.h and, when
# MROS_EXPORT_DIR is set, also into that export dir for a firmware
# (genmros owns its layout: see colcon_mros/export/export_dir.py).

if(NOT GENMROS_BIN)
  message(FATAL_ERROR "genmros: the genmros program was not found; reinstall colcon-mros "
    "(scripts/setup.sh), or set ROS_LANG_DISABLE=genmros to build without mROS headers")
endif()

# Not include/: the headers have the same names and namespaces as gencpp's.
set(genmros_INSTALL_DIR share/genmros/include)

# The export is a cache setting, so a later configure (a CMakeLists.txt edit,
# a new package) keeps it until -DMROS_EXPORT_DIR= turns it off. The
# environment variable sets it where the cache has no say yet: on a package's
# first configure.
if(NOT DEFINED CACHE{MROS_EXPORT_DIR} AND NOT "$ENV{MROS_EXPORT_DIR}" STREQUAL "")
  set(MROS_EXPORT_DIR "$ENV{MROS_EXPORT_DIR}" CACHE PATH
    "genmros: also collect every mROS header of the workspace in this dir (empty: off)")
elseif(NOT "$ENV{MROS_EXPORT_DIR}" STREQUAL "")
  get_filename_component(_genmros_environment_dir "$ENV{MROS_EXPORT_DIR}" ABSOLUTE)
  set(_genmros_cache_dir "$CACHE{MROS_EXPORT_DIR}")
  if(_genmros_cache_dir)
    get_filename_component(_genmros_cache_dir "${_genmros_cache_dir}" ABSOLUTE)
  endif()
  if(NOT _genmros_environment_dir STREQUAL _genmros_cache_dir)
    message(WARNING "genmros: MROS_EXPORT_DIR in the environment ('$ENV{MROS_EXPORT_DIR}') is "
      "ignored: the CMake cache holds '$CACHE{MROS_EXPORT_DIR}'; change it with "
      "-DMROS_EXPORT_DIR=...")
  endif()
endif()
if(MROS_EXPORT_DIR)
  get_filename_component(MROS_EXPORT_DIR "${MROS_EXPORT_DIR}" ABSOLUTE)
endif()

# mros_generate.cmake, the firmware-side module an export dir's
# mros_export.cmake includes, is installed beside this file.
set(_GENMROS_CMAKE_DIR "${CMAKE_CURRENT_LIST_DIR}")

macro(_generate_msg_mros ARG_PKG ARG_MSG ARG_IFLAGS ARG_MSG_DEPS ARG_GEN_OUTPUT_DIR)
  _genmros_note_file("${ARG_MSG}" "${ARG_IFLAGS}" "${ARG_MSG_DEPS}")
endmacro()

macro(_generate_srv_mros ARG_PKG ARG_SRV ARG_IFLAGS ARG_MSG_DEPS ARG_GEN_OUTPUT_DIR)
  _genmros_note_file("${ARG_SRV}" "${ARG_IFLAGS}" "${ARG_MSG_DEPS}")
endmacro()

# Macros, not functions: the notes and genmsg's ALL_GEN_OUTPUT_FILES_mros
# live in the package's scope.
macro(_genmros_note_file ARG_FILE ARG_IFLAGS ARG_FILE_DEPS)
  list(APPEND _genmros_files "${ARG_FILE}")
  list(APPEND _genmros_depends ${ARG_FILE_DEPS})
  set(_genmros_iflags "${ARG_IFLAGS}")
endmacro()

# genmsg's header names (as gencpp's CMake has them): <Type>.h, and for a
# service one header per half besides (<Service>Request.h, <Service>Response.h:
# GENMROS_SERVICE_HALVES of genmros-names.cmake, which genmrosConfig.cmake
# includes through mros_generate.cmake).
macro(_genmros_devel_headers ARG_GEN_OUTPUT_DIR)
  set(_genmros_headers "")
  foreach(_genmros_file ${_genmros_files})
    get_filename_component(_genmros_name "${_genmros_file}" NAME_WE)
    list(APPEND _genmros_headers "${ARG_GEN_OUTPUT_DIR}/${_genmros_name}.h")
    if(_genmros_file MATCHES "\\.srv$")
      foreach(_genmros_half ${GENMROS_SERVICE_HALVES})
        list(APPEND _genmros_headers "${ARG_GEN_OUTPUT_DIR}/${_genmros_name}${_genmros_half}.h")
      endforeach()
    endif()
  endforeach()
endmacro()

# With an export dir, genmros checks and prepares it once per CMake run and
# says where the packages' run records in it go (the layout is genmros').
macro(_genmros_configure_export_dir)
  get_property(_genmros_export_records GLOBAL PROPERTY "_genmros_export_records:${MROS_EXPORT_DIR}")
  if(NOT _genmros_export_records)
    set(_genmros_answer "${CMAKE_BINARY_DIR}/genmros/export-dir.cmake")
    execute_process(
      COMMAND "${GENMROS_BIN}" catkin-export-dir "${MROS_EXPORT_DIR}"
        --cmake-file "${_genmros_answer}" --cmake-module "${_GENMROS_CMAKE_DIR}/mros_generate.cmake"
      RESULT_VARIABLE _genmros_result ERROR_VARIABLE _genmros_error)
    if(NOT _genmros_result EQUAL 0)
      string(STRIP "${_genmros_error}" _genmros_error)
      string(REGEX REPLACE "^genmros: error: " "genmros: " _genmros_error "${_genmros_error}")
      message(FATAL_ERROR "${_genmros_error}")
    endif()
    include("${_genmros_answer}")
    set_property(GLOBAL PROPERTY "_genmros_export_records:${MROS_EXPORT_DIR}"
      "${_genmros_export_records}")
  endif()
endmacro()

macro(_generate_module_mros ARG_PKG ARG_GEN_OUTPUT_DIR ARG_GENERATED_FILES)
  if(MROS_EXPORT_DIR)
    _genmros_configure_export_dir()
  endif()
  # Made now, not at build time: genmsg installs the package's output
  # directory only if it exists when the package is configured.
  file(MAKE_DIRECTORY "${ARG_GEN_OUTPUT_DIR}")
  if(_genmros_files)
    get_filename_component(_genmros_include_root "${ARG_GEN_OUTPUT_DIR}" DIRECTORY)
    get_filename_component(_genmros_share_dir "${_genmros_include_root}" DIRECTORY)
    # Beside the include root, not in it: genmsg installs the package's dir.
    set(_genmros_records "${_genmros_share_dir}/runs/${ARG_PKG}")
    set(_genmros_export_args "")
    if(MROS_EXPORT_DIR)
      list(APPEND _genmros_records "${_genmros_export_records}/${ARG_PKG}")
      set(_genmros_export_args --add-to-export-dir "${MROS_EXPORT_DIR}"
        --cmake-module "${_GENMROS_CMAKE_DIR}/mros_generate.cmake")
    endif()
    _genmros_devel_headers("${ARG_GEN_OUTPUT_DIR}")
    if(_genmros_depends)
      list(REMOVE_DUPLICATES _genmros_depends)
    endif()
    # What make cannot see in the files' times, a removed definition or
    # another export dir, makes it call genmros too (the run record says what
    # to generate). Written only when it changes.
    set(_genmros_inputs "${CMAKE_CURRENT_BINARY_DIR}/genmros/${ARG_PKG}.inputs")
    string(REPLACE ";" "\n" _genmros_inputs_text "${_genmros_files};${MROS_EXPORT_DIR}")
    file(GENERATE OUTPUT "${_genmros_inputs}" CONTENT "${_genmros_inputs_text}\n")
    # make and ninja know the run by its records; the headers are byproducts,
    # which genmros rewrites only where their text changes. genmros writes
    # the export dir atomically and under its lock, so packages built in
    # parallel can share it.
    set(_genmros_record_args "")
    foreach(_genmros_record ${_genmros_records})
      list(APPEND _genmros_record_args --record "${_genmros_record}")
    endforeach()
    add_custom_command(OUTPUT ${_genmros_records}
      BYPRODUCTS ${_genmros_headers}
      COMMAND "${GENMROS_BIN}" generate ${_genmros_files} ${_genmros_iflags} -p "${ARG_PKG}"
        -o "${ARG_GEN_OUTPUT_DIR}" ${_genmros_export_args} ${_genmros_record_args}
        --all-of-package
      DEPENDS "${GENMROS_BIN}" ${_genmros_files} ${_genmros_depends} "${_genmros_inputs}"
      COMMENT "Generating mROS headers for package ${ARG_PKG}"
      VERBATIM)
    list(APPEND ALL_GEN_OUTPUT_FILES_mros ${_genmros_records})
    # The support headers beside the packages' dirs.
    list(TRANSFORM GENMROS_SUPPORT_HEADERS PREPEND "${_genmros_include_root}/"
      OUTPUT_VARIABLE _genmros_support_headers)
    install(FILES ${_genmros_support_headers}
      DESTINATION "${genmros_INSTALL_DIR}")
  endif()
  unset(_genmros_files)
  unset(_genmros_depends)
endmacro()
