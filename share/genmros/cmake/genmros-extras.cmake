# genmros as a genmsg message generator, beside gencpp and genpy.
#
# genmsg's generate_messages() calls the three macros below for every package
# (the language name is "mros": genmsg strips the "gen" of "genmros"):
#   _generate_msg_mros / _generate_srv_mros  one custom command per .msg/.srv
#   _generate_module_mros                    once per package, after them
# The headers go to ${CATKIN_DEVEL_PREFIX}/${genmros_INSTALL_DIR}/<pkg>/<Type>.h
# and, when MROS_EXPORT_DIR is set (CMake variable or environment), also to
# ${MROS_EXPORT_DIR}/include/<pkg>/<Type>.h, with the headers of every type
# they contain (installed packages' too), and the .msg/.srv files and the
# package.xml under ${MROS_EXPORT_DIR}/share/<pkg>/ (what mros_import_messages()
# reads to write a firmware's aggregates), and ${MROS_EXPORT_DIR}/mros_export.cmake
# for a firmware to include(). Headers and definitions no type needs any more
# leave the export dir (genmros keeps its claims in ${MROS_EXPORT_DIR}/.genmros).

if(NOT GENMROS_BIN)
  message(FATAL_ERROR "genmros: the genmros program was not found; reinstall colcon-mros "
    "(scripts/setup.sh), or set ROS_LANG_DISABLE=genmros to build without mROS headers")
endif()

# Not include/: the headers have the same names and namespaces as gencpp's.
set(genmros_INSTALL_DIR share/genmros/include)

# The support header every generated header includes; genmros writes it to
# the include root, the parent of each package's output directory.
set(GENMROS_SUPPORT_HEADER mros_message_support.h)

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

# Fail at configure time, naming the directory, if the export dir cannot
# take the headers.
function(_genmros_check_export_dir ARG_DIR)
  set(probe "${ARG_DIR}")
  while(NOT EXISTS "${probe}")
    get_filename_component(probe "${probe}" DIRECTORY)
  endwhile()
  if(NOT IS_DIRECTORY "${probe}")
    message(FATAL_ERROR "genmros: MROS_EXPORT_DIR '${ARG_DIR}' cannot be created: "
      "'${probe}' is not a directory")
  endif()
  file(MAKE_DIRECTORY "${ARG_DIR}/include")
  # DIR/share/<pkg>/package.xml must not look like a second copy of each
  # package to catkin or colcon when DIR is inside the workspace.
  file(TOUCH "${ARG_DIR}/COLCON_IGNORE")
endfunction()

# mros_generate.cmake, the firmware-side module, is installed beside this file.
set(_GENMROS_CMAKE_DIR "${CMAKE_CURRENT_LIST_DIR}")

if(MROS_EXPORT_DIR)
  get_filename_component(MROS_EXPORT_DIR "${MROS_EXPORT_DIR}" ABSOLUTE)
  _genmros_check_export_dir("${MROS_EXPORT_DIR}")
  # What a firmware include()s, as colcon build --mros-export writes it;
  # rewritten only when its text changes.
  configure_file("${_GENMROS_CMAKE_DIR}/mros_export.cmake.in" "${MROS_EXPORT_DIR}/mros_export.cmake" @ONLY)
endif()

# The header names one .msg or .srv file produces, relative to its package dir.
function(_genmros_header_names ARG_FILE ARG_OUTPUT_VAR)
  get_filename_component(type_name "${ARG_FILE}" NAME_WE)
  set(names "${type_name}.h")
  if(ARG_FILE MATCHES "\\.srv$")
    list(APPEND names "${type_name}Request.h" "${type_name}Response.h")
  endif()
  set(${ARG_OUTPUT_VAR} ${names} PARENT_SCOPE)
endfunction()

macro(_generate_msg_mros ARG_PKG ARG_MSG ARG_IFLAGS ARG_MSG_DEPS ARG_GEN_OUTPUT_DIR)
  _genmros_add_command("${ARG_PKG}" "${ARG_MSG}" "${ARG_IFLAGS}" "${ARG_MSG_DEPS}"
    "${ARG_GEN_OUTPUT_DIR}" msg)
endmacro()

macro(_generate_srv_mros ARG_PKG ARG_SRV ARG_IFLAGS ARG_MSG_DEPS ARG_GEN_OUTPUT_DIR)
  _genmros_add_command("${ARG_PKG}" "${ARG_SRV}" "${ARG_IFLAGS}" "${ARG_MSG_DEPS}"
    "${ARG_GEN_OUTPUT_DIR}" srv)
endmacro()

# A macro, not a function: genmsg collects ALL_GEN_OUTPUT_FILES_mros in the
# caller's scope.
macro(_genmros_add_command ARG_PKG ARG_FILE ARG_IFLAGS ARG_FILE_DEPS ARG_GEN_OUTPUT_DIR ARG_KIND)
  # Made now, not at build time: genmsg installs this directory only if it
  # exists when the package is configured.
  file(MAKE_DIRECTORY "${ARG_GEN_OUTPUT_DIR}")
  _genmros_header_names("${ARG_FILE}" _genmros_names)
  get_filename_component(_genmros_file_name "${ARG_FILE}" NAME)
  set(_genmros_outputs "")
  foreach(_genmros_name ${_genmros_names})
    list(APPEND _genmros_outputs "${ARG_GEN_OUTPUT_DIR}/${_genmros_name}")
  endforeach()

  set(_genmros_export_args "")
  if(MROS_EXPORT_DIR)
    # The same genmros run fills the export dir: this file's headers, those
    # of every type they contain (std_msgs/Header too, so the export needs no
    # ROS installed beside it), and their definitions under share/. genmros
    # writes atomically, so packages built in parallel can share the dir.
    set(_genmros_export_args --export-dir "${MROS_EXPORT_DIR}")
    foreach(_genmros_name ${_genmros_names})
      list(APPEND _genmros_outputs "${MROS_EXPORT_DIR}/include/${ARG_PKG}/${_genmros_name}")
    endforeach()
    list(APPEND _genmros_outputs "${MROS_EXPORT_DIR}/share/${ARG_PKG}/${ARG_KIND}/${_genmros_file_name}")
  endif()

  # genmros leaves a header with unchanged content untouched; the touch tells
  # make that this rule has run, so a build with nothing changed runs no
  # generator at all.
  add_custom_command(OUTPUT ${_genmros_outputs}
    COMMAND "${GENMROS_BIN}" "${ARG_FILE}" ${ARG_IFLAGS} -p "${ARG_PKG}" -o "${ARG_GEN_OUTPUT_DIR}"
      ${_genmros_export_args}
    COMMAND "${CMAKE_COMMAND}" -E touch_nocreate ${_genmros_outputs}
    DEPENDS "${GENMROS_BIN}" "${ARG_FILE}" ${ARG_FILE_DEPS}
    COMMENT "Generating mROS headers from ${ARG_PKG}/${_genmros_file_name}"
    VERBATIM)
  list(APPEND ALL_GEN_OUTPUT_FILES_mros ${_genmros_outputs})
endmacro()

# Remove the genmros headers in ARG_DIR that the package no longer defines,
# and, in an export dir, the .msg/.srv copies they came from and their
# claims (genmros' record of what each definition put into the dir). Only
# files that carry genmros' marker are removed. Sets ARG_REMOVED_VAR when it
# removed a header.
function(_genmros_remove_stale ARG_DIR ARG_KEEP ARG_DEFINITIONS_DIR ARG_CLAIMS_DIR ARG_REMOVED_VAR)
  set(removed FALSE)
  file(GLOB headers "${ARG_DIR}/*.h")
  foreach(header ${headers})
    get_filename_component(name "${header}" NAME)
    list(FIND ARG_KEEP "${name}" index)
    if(index EQUAL -1)
      file(STRINGS "${header}" marker LIMIT_COUNT 1 LIMIT_INPUT 512 REGEX "Generated by genmros")
      if(marker)
        file(REMOVE "${header}")
        set(removed TRUE)
        if(ARG_DEFINITIONS_DIR)
          get_filename_component(type_name "${name}" NAME_WE)
          file(REMOVE "${ARG_DEFINITIONS_DIR}/msg/${type_name}.msg"
                      "${ARG_DEFINITIONS_DIR}/srv/${type_name}.srv"
                      "${ARG_CLAIMS_DIR}/msg/${type_name}.msg"
                      "${ARG_CLAIMS_DIR}/srv/${type_name}.srv")
        endif()
      endif()
    endif()
  endforeach()
  set(${ARG_REMOVED_VAR} ${removed} PARENT_SCOPE)
endfunction()

macro(_generate_module_mros ARG_PKG ARG_GEN_OUTPUT_DIR ARG_GENERATED_FILES)
  # The names of the headers (and exported definitions) the package has now.
  set(_genmros_keep "")
  foreach(_genmros_output ${ARG_GENERATED_FILES})
    get_filename_component(_genmros_name "${_genmros_output}" NAME)
    list(APPEND _genmros_keep "${_genmros_name}")
  endforeach()
  # A .msg removed from the package: its header goes on the next configure.
  _genmros_remove_stale("${ARG_GEN_OUTPUT_DIR}" "${_genmros_keep}" "" "" _genmros_removed)
  if(MROS_EXPORT_DIR)
    _genmros_remove_stale("${MROS_EXPORT_DIR}/include/${ARG_PKG}" "${_genmros_keep}"
      "${MROS_EXPORT_DIR}/share/${ARG_PKG}" "${MROS_EXPORT_DIR}/.genmros/claims/${ARG_PKG}"
      _genmros_removed)
    if(_genmros_removed)
      # The types only the removed definitions contained leave too.
      execute_process(COMMAND "${GENMROS_BIN}" prune-export "${MROS_EXPORT_DIR}"
        RESULT_VARIABLE _genmros_result)
      if(NOT _genmros_result EQUAL 0)
        message(FATAL_ERROR "genmros: could not prune MROS_EXPORT_DIR '${MROS_EXPORT_DIR}'")
      endif()
    endif()
    # Built, not configured: an export dir removed by hand comes back whole.
    set(_genmros_manifest "${MROS_EXPORT_DIR}/share/${ARG_PKG}/package.xml")
    add_custom_command(OUTPUT "${_genmros_manifest}"
      COMMAND "${CMAKE_COMMAND}" -E copy "${PROJECT_SOURCE_DIR}/package.xml" "${_genmros_manifest}"
      DEPENDS "${PROJECT_SOURCE_DIR}/package.xml"
      VERBATIM)
    list(APPEND ALL_GEN_OUTPUT_FILES_mros "${_genmros_manifest}")
  endif()
  if(NOT "${ARG_GENERATED_FILES}" STREQUAL "")
    install(FILES "${CATKIN_DEVEL_PREFIX}/${genmros_INSTALL_DIR}/${GENMROS_SUPPORT_HEADER}"
      DESTINATION "${genmros_INSTALL_DIR}")
  endif()
endmacro()
