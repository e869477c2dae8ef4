# mros2 (ROS 2) message headers for a firmware build (plain CMake,
# cross-compiling welcome: nothing of ROS is needed but the export dir and
# genmros).
#
#   mros2_import_messages(TARGET t EXPORT_DIR dir
#                         [PUBLISH pkg/msg/Type ...] [SUBSCRIBE pkg/msg/Type ...]
#                         [TYPES pkg/msg/Type|pkg/srv/Name ...]
#                         [STORAGE heap|bounded] [OPTIONS file ...])
#     Use the ROS 2 types a `colcon build --mros-export dir` exported
#     (dir/mros2): the headers of the PUBLISH, SUBSCRIBE and TYPES types and
#     of every type they contain, and mros2's templates.hpp with the explicit
#     instantiations of its publish and subscribe calls for the PUBLISH and
#     SUBSCRIBE types (genmros mros2-export --publish/--subscribe), so no
#     script greps the app's sources. They are generated at configure time
#     from the definitions the export dir holds, into a directory of t's own,
#     and t (the firmware, or the target that compiles mros2.cpp, which
#     includes templates.hpp) gets it as an include directory. STORAGE
#     bounded holds unbounded strings and sequences in the message, with the
#     maxima of the OPTIONS files (genmros mros2-export --storage bounded
#     --options). A bad definition or an unknown type stops the configure
#     step with genmros' one line; editing a definition or an options file
#     configures again.
# Installed beside mros_generate.cmake; find_package(genmros) includes both.

find_program(GENMROS_BIN genmros
  HINTS "${CMAKE_CURRENT_LIST_DIR}/../../../bin"
  DOC "genmros, the mROS message generator of colcon-mros")

function(mros2_import_messages)
  cmake_parse_arguments(ARG "" "TARGET;EXPORT_DIR;STORAGE" "TYPES;PUBLISH;SUBSCRIBE;OPTIONS"
    ${ARGN})
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
  if(NOT ARG_EXPORT_DIR OR NOT IS_DIRECTORY "${prefix}/share")
    message(FATAL_ERROR "mros2_import_messages(): EXPORT_DIR '${ARG_EXPORT_DIR}' holds no mros2 "
      "export (no mros2/share); build the ROS 2 workspace with colcon build --mros-export first")
  endif()
  if(NOT ARG_PUBLISH AND NOT ARG_SUBSCRIBE AND NOT ARG_TYPES)
    message(FATAL_ERROR "mros2_import_messages(): name the types (PUBLISH, SUBSCRIBE, TYPES)")
  endif()

  set(output_dir "${CMAKE_CURRENT_BINARY_DIR}/mros2_messages/${ARG_TARGET}")
  set(genmros_args mros2-export --prefix "${prefix}" -o "${output_dir}")
  foreach(kind PUBLISH SUBSCRIBE TYPES)
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

  execute_process(COMMAND "${GENMROS_BIN}" ${genmros_args}
    RESULT_VARIABLE result ERROR_VARIABLE error OUTPUT_QUIET)
  if(NOT result EQUAL 0)
    string(STRIP "${error}" error)
    message(FATAL_ERROR "mros2_import_messages(): ${error}")
  endif()
  file(GLOB_RECURSE definitions "${prefix}/share/*.msg" "${prefix}/share/*.srv"
    "${prefix}/share/*.idl")
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${definitions} ${ARG_OPTIONS})
  target_include_directories(${ARG_TARGET} PUBLIC "${output_dir}")
endfunction()
