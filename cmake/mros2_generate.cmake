# SPDX-License-Identifier: BSD-3-Clause
# mros2 (ROS 2) message headers for a firmware build (plain CMake,
# cross-compiling welcome: nothing of ROS is needed but the export dir and
# genmros).
#
#   mros2_import_messages(TARGET t EXPORT_DIR dir [PREFIXES prefix ...]
#                         [PUBLISH [topic:]pkg/msg/Type[:reliable[:depth]] ...]
#                         [SUBSCRIBE [topic:]pkg/msg/Type[:reliable[:depth]] ...]
#                         [SERVE [name:]pkg/srv/Type ...] [CALL [name:]pkg/srv/Type ...]
#                         [TYPES pkg/msg/Type|pkg/srv/Name ...]
#                         [STORAGE heap|bounded] [OPTIONS file ...]
#                         [RTPS_CONFIG rtps/config.h [RECEIVE_LIMIT bytes|file:NAME]
#                          [MROS2_ROOT dir]])
#     Use the ROS 2 types a `colcon build --mros-export dir` exported
#     (dir/mros2), and those of installed ROS 2 prefixes (PREFIXES, e.g.
#     /opt/ros/humble for std_msgs): the headers of the PUBLISH, SUBSCRIBE,
#     SERVE, CALL and TYPES types and of every type they contain, and mros2's
#     templates.hpp with the explicit instantiations of its publish and
#     subscribe calls for the PUBLISH and SUBSCRIBE types, and of its service
#     and client calls for the SERVE and CALL services (genmros mros2-export
#     --publish/--subscribe/--serve/--call; :reliable for an endpoint the app
#     makes with mros2::QoS(depth).reliable(); services need the mros2 patch
#     services-both-ways), so no script greps the app's sources. They are
#     generated at configure time from the definitions the export dir holds,
#     into a directory of t's own, and t (the firmware, or the target that
#     compiles mros2.cpp, which includes templates.hpp) gets it as an include
#     directory. STORAGE
#     bounded holds unbounded strings and sequences in the message, with the
#     maxima of the OPTIONS files (genmros mros2-export --storage bounded
#     --options). RTPS_CONFIG, the board's rtps/config.h, runs the fit check
#     first (genmros mros2-fit): type and topic names, the participant's
#     writers and readers, with RECEIVE_LIMIT each subscribed type's largest
#     sample, with MROS2_ROOT (the firmware's mros2) more than one publisher;
#     templates.hpp's static_asserts hold the same rules and the reader
#     thread's stack wherever mros2.cpp compiles. A bad definition, an
#     unknown type or a misfit stops the configure step with genmros' lines;
#     editing a definition, an options file or the config configures again.
# Installed beside mros_generate.cmake; find_package(genmros) includes both.

find_program(GENMROS_BIN genmros
  HINTS "${CMAKE_CURRENT_LIST_DIR}/../../../bin"
  DOC "genmros, the mROS message generator of colcon-mros")

function(mros2_import_messages)
  cmake_parse_arguments(ARG "" "TARGET;EXPORT_DIR;STORAGE;RTPS_CONFIG;RECEIVE_LIMIT;MROS2_ROOT"
    "TYPES;PUBLISH;SUBSCRIBE;SERVE;CALL;OPTIONS;PREFIXES" ${ARGN})
  if(ARG_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "mros2_import_messages(): unknown arguments: ${ARG_UNPARSED_ARGUMENTS}")
  endif()
  if(NOT ARG_TARGET OR NOT TARGET "${ARG_TARGET}")
    message(FATAL_ERROR "mros2_import_messages(): TARGET '${ARG_TARGET}' is not a target")
  endif()
  if(NOT GENMROS_BIN)
    message(FATAL_ERROR "mros2_import_messages(): genmros was not found; install colcon-mros "
      "(scripts/setup.sh) or set GENMROS_BIN")
  endif()
  get_filename_component(prefix "${ARG_EXPORT_DIR}/mros2" ABSOLUTE)
  get_filename_component(given "${ARG_EXPORT_DIR}" ABSOLUTE)
  get_filename_component(given_name "${given}" NAME)
  if(ARG_EXPORT_DIR AND given_name STREQUAL "mros2" AND IS_DIRECTORY "${given}/share")
    # The mros2 half itself: the export dir is the one colcon wrote, above it.
    get_filename_component(parent "${given}" DIRECTORY)
    message(FATAL_ERROR "mros2_import_messages(): EXPORT_DIR '${ARG_EXPORT_DIR}' is the mros2 "
      "half of an export dir: give the dir colcon build --mros-export wrote, '${parent}'")
  endif()
  if(NOT ARG_EXPORT_DIR OR NOT IS_DIRECTORY "${prefix}/share")
    message(FATAL_ERROR "mros2_import_messages(): EXPORT_DIR '${ARG_EXPORT_DIR}' holds no mros2 "
      "export (no mros2/share); build the ROS 2 workspace with colcon build --mros-export first")
  endif()
  if(NOT ARG_PUBLISH AND NOT ARG_SUBSCRIBE AND NOT ARG_SERVE AND NOT ARG_CALL AND NOT ARG_TYPES)
    message(FATAL_ERROR
      "mros2_import_messages(): name the types (PUBLISH, SUBSCRIBE, SERVE, CALL, TYPES)")
  endif()

  set(output_dir "${CMAKE_CURRENT_BINARY_DIR}/mros2_messages/${ARG_TARGET}")
  set(genmros_args mros2-export --prefix "${prefix}" -o "${output_dir}")
  foreach(installed ${ARG_PREFIXES})
    list(APPEND genmros_args --prefix "${installed}")
  endforeach()
  foreach(kind PUBLISH SUBSCRIBE SERVE CALL TYPES)
    string(TOLOWER "${kind}" flag)
    if(kind STREQUAL "TYPES")
      set(flag "type")
    endif()
    foreach(type ${ARG_${kind}})
      list(APPEND genmros_args "--${flag}" "${type}")
    endforeach()
  endforeach()
  if(ARG_STORAGE)
    list(APPEND genmros_args --storage "${ARG_STORAGE}")
  endif()
  foreach(options ${ARG_OPTIONS})
    get_filename_component(options "${options}" ABSOLUTE)
    list(APPEND genmros_args --options "${options}")
  endforeach()
  set(board_files)
  if(ARG_RTPS_CONFIG)
    get_filename_component(config "${ARG_RTPS_CONFIG}" ABSOLUTE)
    list(APPEND genmros_args --rtps-config "${config}")
    list(APPEND board_files "${config}")
  endif()
  if(ARG_RECEIVE_LIMIT MATCHES "^(.+):([A-Za-z_][A-Za-z0-9_]*)$")
    # FILE:NAME: the file as the config is, absolute (genmros runs in the
    # build dir) and a configure dependency.
    set(limit_name "${CMAKE_MATCH_2}")
    get_filename_component(limit_file "${CMAKE_MATCH_1}" ABSOLUTE)
    list(APPEND genmros_args --receive-limit "${limit_file}:${limit_name}")
    list(APPEND board_files "${limit_file}")
  elseif(ARG_RECEIVE_LIMIT)
    list(APPEND genmros_args --receive-limit "${ARG_RECEIVE_LIMIT}")
  endif()
  if(ARG_MROS2_ROOT)
    get_filename_component(mros2_root "${ARG_MROS2_ROOT}" ABSOLUTE)
    list(APPEND genmros_args --mros2-root "${mros2_root}")
    list(APPEND board_files "${mros2_root}/include/mros2.h")
  endif()

  execute_process(COMMAND "${GENMROS_BIN}" ${genmros_args}
    RESULT_VARIABLE result ERROR_VARIABLE error OUTPUT_QUIET)
  string(STRIP "${error}" error)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "mros2_import_messages(): ${error}")
  elseif(error)
    message(WARNING "mros2_import_messages(): ${error}")
  endif()
  file(GLOB_RECURSE definitions "${prefix}/share/*.msg" "${prefix}/share/*.srv"
    "${prefix}/share/*.idl")
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${definitions} ${ARG_OPTIONS}
    ${board_files})
  target_include_directories(${ARG_TARGET} PUBLIC "${output_dir}")
endfunction()
