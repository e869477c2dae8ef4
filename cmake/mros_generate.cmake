# SPDX-License-Identifier: BSD-3-Clause
# mROS message headers for a firmware build (plain CMake, cross-compiling
# welcome: nothing of ROS is needed but the .msg files and genmros).
#
#   mros_import_messages(TARGET t EXPORT_DIR dir [TYPES pkg/Type ...]
#                        [STORAGE heap|bounded] [OPTIONS file ...]
#                        [DEFINITION_TEXT full|compact]
#                        [MROS_V1_SETTINGS header ... [FIT_STRICT]])
#     Use the headers a ROS build exported (catkin with MROS_EXPORT_DIR, or
#     colcon build --mros-export): dir/include/<pkg>/<Type>.h. Without TYPES,
#     every type the export dir holds. A ROS build exports heap storage and
#     full definition texts only: with STORAGE bounded or DEFINITION_TEXT
#     compact the headers are generated anew from the definitions the export
#     dir holds (dir/share), for t alone.
#
#   mros_generate_messages(TARGET t TYPES pkg/Type ... [PACKAGE_PATHS dir ...]
#                          [STORAGE heap|bounded] [OPTIONS file ...]
#                          [DEFINITION_TEXT full|compact]
#                          [MROS_V1_SETTINGS header ... [FIT_STRICT]])
#     Generate the headers at build time from .msg files. Each PACKAGE_PATHS
#     entry is an installed prefix (dir/share/<pkg>/msg, as ROS installs them
#     and as an export dir holds them) or a source tree of packages (found
#     by their package.xml): a directory with share/ is passed to genmros
#     mros-v1-export as --prefix, any other as --workspace. Without
#     PACKAGE_PATHS, or with source trees only: the ROS environment, as
#     `genmros mros-v1-export` searches it (rospkg on ROS_PACKAGE_PATH, then
#     CMAKE_PREFIX_PATH).
#
# Both write the per-firmware aggregates for exactly the listed types
# (message_headers.h, message_class_specialization.h, msg_max_size.h, so
# PUB_MSG_MAX_SIZE fits the firmware's types, and mros_v1_delivery.h and
# mros_v1_fit_check.h, which they include) and give t the include
# directories. STORAGE bounded holds strings and variable arrays in the
# message, with the maxima of the OPTIONS files and of each package's
# msg/genmros.options (genmros mros-v1-export --storage bounded --options); editing
# any of them regenerates the headers. DEFINITION_TEXT compact puts each
# type's definition text into the headers without comments and blank lines
# (genmros mros-v1-export --definition-text compact): less flash, same MD5 sums.
# MROS_V1_SETTINGS names the mROS v1 settings headers the firmware builds
# with (the app's mros_usr_config.h, the library's mros_packet_config.h):
# the fit check then stops the configure step and the build with one line per
# setting too small for the types, naming its file, line and the value
# needed (genmros mros-v1-export --mros-v1-settings); FIT_STRICT refuses a type whose
# frame has no maximum too (--fit-strict). Editing a settings header checks
# again. Without it the check still runs when the firmware compiles ros.cpp
# (mros_v1_fit_check.h), where the library's macros are visible.
# Installed as
# <prefix>/share/genmros/cmake/mros_generate.cmake; find_package(genmros)
# includes it.

# GENMROS_FIRMWARE_AGGREGATES and the other names genmros writes.
include("${CMAKE_CURRENT_LIST_DIR}/genmros-names.cmake")

find_program(GENMROS_BIN genmros
  HINTS "${CMAKE_CURRENT_LIST_DIR}/../../../bin"
  DOC "genmros, the mROS message generator of colcon-mros")

# The aggregates of the listed types go to their own directory per target:
# two firmwares in one build tree may use different types.
function(_mros_output_dir ARG_TARGET ARG_OUTPUT_VAR)
  set(${ARG_OUTPUT_VAR} "${CMAKE_CURRENT_BINARY_DIR}/mros_messages/${ARG_TARGET}" PARENT_SCOPE)
endfunction()

function(_mros_check_arguments ARG_FUNCTION ARG_TARGET ARG_UNPARSED)
  if(ARG_UNPARSED)
    message(FATAL_ERROR "${ARG_FUNCTION}() called with unknown arguments: ${ARG_UNPARSED}")
  endif()
  if(NOT ARG_TARGET)
    message(FATAL_ERROR "${ARG_FUNCTION}() needs TARGET")
  endif()
  if(NOT TARGET "${ARG_TARGET}")
    message(FATAL_ERROR "${ARG_FUNCTION}(): '${ARG_TARGET}' is not a target; "
      "call add_executable() or add_library() first")
  endif()
  if(NOT GENMROS_BIN)
    message(FATAL_ERROR "${ARG_FUNCTION}(): genmros not found; install colcon-mros "
      "(scripts/setup.sh) or set GENMROS_BIN")
  endif()
endfunction()

# The run record of the target's genmros mros-v1-export (the rule of
# colcon_mros/export/run_record.py), beside its output directory.
function(_mros_record ARG_OUTPUT_DIR ARG_OUTPUT_VAR)
  set(${ARG_OUTPUT_VAR} "${ARG_OUTPUT_DIR}.d" PARENT_SCOPE)
endfunction()

# A custom target that runs genmros mros-v1-export with ARG_GENMROS_ARGS whenever an
# input its run record names changes, and makes ARG_TARGET build after it
# with ARG_INCLUDE_DIRS.
function(_mros_attach ARG_TARGET ARG_OUTPUT_DIR ARG_GENMROS_ARGS ARG_DEPENDS ARG_INCLUDE_DIRS)
  set(aggregates "")
  foreach(name ${GENMROS_FIRMWARE_AGGREGATES})
    list(APPEND aggregates "${ARG_OUTPUT_DIR}/${name}")
  endforeach()
  _mros_record("${ARG_OUTPUT_DIR}" record)
  # genmros keeps unchanged files as they are, so the firmware's objects are
  # not rebuilt for nothing; the touch marks the rule as done for make.
  add_custom_command(OUTPUT "${record}"
    BYPRODUCTS ${aggregates}
    COMMAND "${GENMROS_BIN}" mros-v1-export ${ARG_GENMROS_ARGS} --record "${record}"
    COMMAND "${CMAKE_COMMAND}" -E touch_nocreate "${record}"
    DEPENDS "${GENMROS_BIN}" ${ARG_DEPENDS}
    COMMENT "Generating mROS message headers for ${ARG_TARGET}"
    VERBATIM)
  add_custom_target(${ARG_TARGET}_mros_messages DEPENDS "${record}")
  add_dependencies(${ARG_TARGET} ${ARG_TARGET}_mros_messages)
  target_include_directories(${ARG_TARGET} PUBLIC ${ARG_INCLUDE_DIRS})
endfunction()

# genmros' arguments for the headers' form, from STORAGE, OPTIONS and
# DEFINITION_TEXT as given: genmros has the defaults and checks the values
# (at configure time, see _mros_export_now).
function(_mros_form_args ARG_STORAGE ARG_OPTIONS ARG_DEFINITION_TEXT ARG_OUTPUT_VAR)
  set(arguments "")
  if(ARG_STORAGE)
    list(APPEND arguments --storage "${ARG_STORAGE}")
  endif()
  if(ARG_DEFINITION_TEXT)
    list(APPEND arguments --definition-text "${ARG_DEFINITION_TEXT}")
  endif()
  foreach(file ${ARG_OPTIONS})
    get_filename_component(file "${file}" ABSOLUTE)
    list(APPEND arguments --options "${file}")
  endforeach()
  set(${ARG_OUTPUT_VAR} ${arguments} PARENT_SCOPE)
endfunction()

# genmros' arguments for the fit check against the mROS v1 settings headers.
function(_mros_fit_args ARG_SETTINGS ARG_FIT_STRICT ARG_OUTPUT_VAR)
  set(arguments "")
  foreach(file ${ARG_SETTINGS})
    get_filename_component(file "${file}" ABSOLUTE)
    list(APPEND arguments --mros-v1-settings "${file}")
  endforeach()
  if(ARG_FIT_STRICT)
    list(APPEND arguments --fit-strict)
  endif()
  set(${ARG_OUTPUT_VAR} ${arguments} PARENT_SCOPE)
endfunction()

# Runs genmros mros-v1-export once at configure time, so a bad type, package or
# options file fails the configure step with genmros' one line rather than
# the first build, and sets ARG_OUTPUT_VAR to the inputs its run record
# names: every .msg/.srv and options file the headers come from, wherever
# genmros found them, so that a change to any of them regenerates the headers.
function(_mros_export_now ARG_FUNCTION ARG_GENMROS_ARGS ARG_OUTPUT_DIR ARG_OUTPUT_VAR)
  _mros_record("${ARG_OUTPUT_DIR}" record)
  execute_process(COMMAND "${GENMROS_BIN}" mros-v1-export ${ARG_GENMROS_ARGS} --record "${record}"
    RESULT_VARIABLE result ERROR_VARIABLE error OUTPUT_QUIET)
  # genmros' error lines, one per problem (argparse puts its usage before
  # them), and its warnings; a CMake list splits at ';', so the lines keep
  # theirs as a placeholder until they are elements.
  string(REPLACE ";" "<semicolon>" protected "${error}")
  string(REGEX MATCHALL "[^\n]*(error|warning): [^\n]*" lines "${protected}")
  string(REPLACE "<semicolon>" "\\;" lines "${lines}")
  foreach(line ${lines})
    if(line MATCHES "warning: ")
      message(WARNING "${ARG_FUNCTION}(): ${line}")
    endif()
  endforeach()
  if(NOT result EQUAL 0)
    set(error_lines "")
    foreach(line ${lines})
      if(line MATCHES "error: ")
        string(APPEND error_lines "\n${ARG_FUNCTION}(): ${line}")
      endif()
    endforeach()
    if(NOT error_lines)
      string(STRIP "${error}" error_lines)
    endif()
    message(FATAL_ERROR "${error_lines}")
  endif()
  # The record is a make rule too: after its main rule, one rule "<input>:"
  # per input, in make's escapes.
  set(inputs "")
  file(STRINGS "${record}" rules REGEX "^[^#].*:$")
  foreach(rule ${rules})
    string(REGEX REPLACE ":$" "" input "${rule}")
    string(REPLACE "\\ " " " input "${input}")
    string(REPLACE "\\#" "#" input "${input}")
    string(REPLACE "$$" "$" input "${input}")
    list(APPEND inputs "${input}")
  endforeach()
  set(${ARG_OUTPUT_VAR} ${inputs} PARENT_SCOPE)
endfunction()

function(mros_import_messages)
  cmake_parse_arguments(ARG "FIT_STRICT" "TARGET;EXPORT_DIR;STORAGE;DEFINITION_TEXT"
    "TYPES;OPTIONS;MROS_V1_SETTINGS" ${ARGN})
  _mros_check_arguments(mros_import_messages "${ARG_TARGET}" "${ARG_UNPARSED_ARGUMENTS}")
  get_filename_component(export_dir "${ARG_EXPORT_DIR}" ABSOLUTE)
  # An export dir describes itself to CMake in mros_export.cmake (genmros
  # writes it): MROS_EXPORT_INCLUDE_DIR and every type, MROS_EXPORT_TYPES.
  if(NOT ARG_EXPORT_DIR OR NOT EXISTS "${export_dir}/mros_export.cmake")
    message(FATAL_ERROR "mros_import_messages(): EXPORT_DIR '${ARG_EXPORT_DIR}' holds no "
      "genmros export (no mros_export.cmake); build the ROS workspace with "
      "MROS_EXPORT_DIR or colcon build --mros-export first")
  endif()
  include("${export_dir}/mros_export.cmake")

  set(types ${ARG_TYPES})
  if(NOT types)
    set(types ${MROS_EXPORT_TYPES})
  endif()
  if(NOT types)
    message(FATAL_ERROR "mros_import_messages(): EXPORT_DIR '${export_dir}' holds no message types")
  endif()

  _mros_form_args("${ARG_STORAGE}" "${ARG_OPTIONS}" "${ARG_DEFINITION_TEXT}" form_args)
  _mros_fit_args("${ARG_MROS_V1_SETTINGS}" "${ARG_FIT_STRICT}" fit_args)
  set(genmros_args --export-dir "${export_dir}")
  foreach(type ${types})
    list(FIND MROS_EXPORT_TYPES "${type}" index)
    if(index EQUAL -1)
      message(FATAL_ERROR "mros_import_messages(): type '${type}' is not in the export "
        "dir '${export_dir}'")
    endif()
    list(APPEND genmros_args --type "${type}")
  endforeach()

  _mros_output_dir(${ARG_TARGET} output_dir)
  list(APPEND genmros_args -o "${output_dir}" ${form_args} ${fit_args})
  _mros_export_now(mros_import_messages "${genmros_args}" "${output_dir}" inputs)
  # genmros writes the aggregates, and every header too where the export's
  # are not in the form asked for: then those stay out of t.
  if(EXISTS "${output_dir}/${GENMROS_SUPPORT_HEADER}")
    set(include_dirs "${output_dir}")
  else()
    set(include_dirs "${output_dir};${MROS_EXPORT_INCLUDE_DIR}")
  endif()
  # A ROS build that changes the export rewrites its definitions and, when
  # types come or go, mros_export.cmake.
  list(APPEND inputs "${export_dir}/mros_export.cmake")
  _mros_attach(${ARG_TARGET} "${output_dir}" "${genmros_args}" "${inputs}" "${include_dirs}")
endfunction()

function(mros_generate_messages)
  cmake_parse_arguments(ARG "FIT_STRICT" "TARGET;STORAGE;DEFINITION_TEXT"
    "TYPES;PACKAGE_PATHS;OPTIONS;MROS_V1_SETTINGS" ${ARGN})
  _mros_check_arguments(mros_generate_messages "${ARG_TARGET}" "${ARG_UNPARSED_ARGUMENTS}")
  if(NOT ARG_TYPES)
    message(FATAL_ERROR "mros_generate_messages(): TYPES lists no message type")
  endif()

  _mros_form_args("${ARG_STORAGE}" "${ARG_OPTIONS}" "${ARG_DEFINITION_TEXT}" genmros_args)
  _mros_fit_args("${ARG_MROS_V1_SETTINGS}" "${ARG_FIT_STRICT}" fit_args)
  list(APPEND genmros_args ${fit_args})
  # An installed prefix has share/ (genmros' own rule for a package path).
  foreach(path ${ARG_PACKAGE_PATHS})
    get_filename_component(path "${path}" ABSOLUTE)
    if(NOT IS_DIRECTORY "${path}")
      message(FATAL_ERROR "mros_generate_messages(): PACKAGE_PATHS: ${path}: not a "
        "directory: a package path is a source tree of packages or an installed prefix "
        "(with share/<pkg>/msg)")
    elseif(IS_DIRECTORY "${path}/share")
      list(APPEND genmros_args --prefix "${path}")
    else()
      list(APPEND genmros_args --workspace "${path}")
    endif()
  endforeach()
  foreach(type ${ARG_TYPES})
    list(APPEND genmros_args --type "${type}")
  endforeach()

  _mros_output_dir(${ARG_TARGET} output_dir)
  list(APPEND genmros_args -o "${output_dir}")

  _mros_export_now(mros_generate_messages "${genmros_args}" "${output_dir}" inputs)
  _mros_attach(${ARG_TARGET} "${output_dir}" "${genmros_args}" "${inputs}" "${output_dir}")
endfunction()
