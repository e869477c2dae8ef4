# SPDX-License-Identifier: BSD-3-Clause
# mros2-posix' top-level CMakeLists.txt includes workspace/<app>/Filelists.cmake for the
# app's sources (apl_SRCS). app.cpp is ours, so it alone is held to -Wall -Wextra; the
# options say which mros2 it is built against (testing/mros2_posix.py passes them).
option(APP_ECHO_PUBLISHER "echo requests as std_msgs/String on a publisher of their own" OFF)
option(APP_SETS_RTPS_ADDRESS "mros2 >= 0.5 takes the RTPS address at run time" OFF)
set(apl_SRCS ${PROJECT_SOURCE_DIR}/workspace/${MROS2_APPNAME}/app.cpp)
# embeddedRTPS' headers are not ours: as system headers their warnings stay out of ours.
set_property(SOURCE ${apl_SRCS} APPEND PROPERTY COMPILE_OPTIONS
             -Wall -Wextra -isystem ${PROJECT_SOURCE_DIR}/mros2/embeddedRTPS/include)
foreach(switch APP_ECHO_PUBLISHER APP_SETS_RTPS_ADDRESS)
  if(${switch})
    set_property(SOURCE ${apl_SRCS} APPEND PROPERTY COMPILE_DEFINITIONS ${switch})
  endif()
endforeach()
