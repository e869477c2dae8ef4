# genmros as a genmsg message generator, beside gencpp and genpy.
#
# genmsg's generate_messages() calls the three macros below for every package
# (the language name is "mros": genmsg strips the "gen" of "genmros"):
#   _generate_msg_mros / _generate_srv_mros  once per .msg/.srv: noted here
#   _generate_module_mros                    once per package, after them
# The last asks genmros what the package's headers are (genmros
# catkin-package, which also tidies up after removed files) and adds one
# custom command for the whole package: one genmros process generates every
# header the package has, and after a change only those of the files whose
# definitions changed. The headers go to
# ${CATKIN_DEVEL_PREFIX}/${genmros_INSTALL_DIR}/<pkg>/<Type>.h and, when
# MROS_EXPORT_DIR is set, also into that export dir for a firmware
# (genmros owns its layout: see colcon_mros/export_dir.py).

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

macro(_generate_module_mros ARG_PKG ARG_GEN_OUTPUT_DIR ARG_GENERATED_FILES)
  set(_genmros_export_args "")
  if(MROS_EXPORT_DIR)
    set(_genmros_export_args --export-dir "${MROS_EXPORT_DIR}"
      --cmake-module "${_GENMROS_CMAKE_DIR}/mros_generate.cmake")
  endif()
  set(_genmros_outputs_file "${CMAKE_CURRENT_BINARY_DIR}/genmros/${ARG_PKG}-outputs.cmake")
  execute_process(
    COMMAND "${GENMROS_BIN}" catkin-package -p "${ARG_PKG}" -o "${ARG_GEN_OUTPUT_DIR}"
      --cmake-file "${_genmros_outputs_file}" ${_genmros_export_args} ${_genmros_files}
    RESULT_VARIABLE _genmros_result ERROR_VARIABLE _genmros_error)
  if(NOT _genmros_result EQUAL 0)
    string(STRIP "${_genmros_error}" _genmros_error)
    string(REGEX REPLACE "^genmros: error: " "genmros: " _genmros_error "${_genmros_error}")
    message(FATAL_ERROR "${_genmros_error}")
  endif()
  include("${_genmros_outputs_file}")

  if(_genmros_files)
    if(_genmros_depends)
      list(REMOVE_DUPLICATES _genmros_depends)
    endif()
    # make and ninja know the run by its stamps; the headers are byproducts,
    # which genmros rewrites only where their text changes. genmros writes
    # the export dir atomically and under its lock, so packages built in
    # parallel can share it.
    set(_genmros_stamp_args "")
    foreach(_genmros_stamp ${_genmros_stamps})
      list(APPEND _genmros_stamp_args --stamp "${_genmros_stamp}")
    endforeach()
    add_custom_command(OUTPUT ${_genmros_stamps}
      BYPRODUCTS ${_genmros_outputs}
      COMMAND "${GENMROS_BIN}" ${_genmros_files} ${_genmros_iflags} -p "${ARG_PKG}"
        -o "${ARG_GEN_OUTPUT_DIR}" ${_genmros_export_args} ${_genmros_stamp_args}
      DEPENDS "${GENMROS_BIN}" ${_genmros_files} ${_genmros_depends}
      COMMENT "Generating mROS headers for package ${ARG_PKG}"
      VERBATIM)
    list(APPEND ALL_GEN_OUTPUT_FILES_mros ${_genmros_stamps})
    install(FILES ${_genmros_support_header} DESTINATION "${genmros_INSTALL_DIR}")
  endif()
  unset(_genmros_files)
  unset(_genmros_depends)
endmacro()
