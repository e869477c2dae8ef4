# SPDX-License-Identifier: BSD-3-Clause
# mros2_pc.mk: an unmodified mros2 app and library, built for a PC.
#
# `genmros mros2-pc APP_DIR` runs this with the variables below; it has
# written genmros' headers and templates.hpp into $(BUILD)/include and the
# stand-ins' settings (mros2_pc_settings.h) into $(BUILD)/settings.
#
#   MROS2_SOURCES  the library's sources: mros2's src/mros2.cpp, embeddedRTPS
#                  and Micro-CDR, as the checkout's CMakeLists.txt lists them
#   MROS2_INCLUDE_DIRS  the library's include directories (the same file's)
#   APP_SOURCES    the app's sources; APP_DIR its directory
#   CONFIG_DIR     the directory holding the board's rtps/config.h (or the
#                  copy genmros changed to fit mros2)
#   TARGET         arm: 32-bit ARM Linux (static, run with qemu-arm), each
#                  thread on its board stack; native: this PC
#   BUILD          the output directory; PROGRAM the program's name
#   SANITIZER_FLAGS  added to every compile and the link (--sanitize, and
#                 the flags a bench adds, such as --coverage)
#   STAND_IN_FLAGS the stand-ins' own defines; APP_FLAGS the app's (-D)
#   FLAGS_STAMP    a file genmros rewrites when the flags change: every
#                  object depends on it
#
# Goals, one step each: library (mros2 and the stand-ins), app, program
# (the link).

PC_TARGET := $(patsubst %/,%,$(dir $(lastword $(MAKEFILE_LIST))))

ifeq ($(TARGET),arm)
CROSS := arm-linux-gnueabihf-
# Thumb-2 with a double-precision FPU and no unaligned access, as a
# Cortex-M7 board runs it; static, so that qemu-arm needs no ARM libraries.
# -Wno-psabi: GCC's note that passing a std::vector<double> changed in GCC
# 7.1 is about linking with objects of older compilers, which none here is.
CPU_FLAGS := -mthumb -mcpu=cortex-a7 -mfpu=vfpv4-d16 -mfloat-abi=hard -mno-unaligned-access \
             -Wno-psabi
LINK_FLAGS := -static
else ifeq ($(TARGET),native)
CROSS :=
CPU_FLAGS :=
LINK_FLAGS :=
else
$(error mros2_pc.mk: TARGET is '$(TARGET)', not arm or native)
endif
CC := $(CROSS)gcc
CXX := $(CROSS)g++

OBJ_DIR := $(BUILD)/obj
# genmros' headers and templates.hpp first, then the settings, the board's
# config, the stand-ins' headers, the app's and the library's.
INCLUDES := -I$(BUILD)/include -I$(BUILD)/settings -I$(CONFIG_DIR) -I$(PC_TARGET)/include \
            -I$(APP_DIR) $(addprefix -I,$(MROS2_INCLUDE_DIRS))
COMMON_FLAGS := $(CPU_FLAGS) -g -pthread -MMD -MP $(SANITIZER_FLAGS) $(INCLUDES)
# The library and the app optimized for size, as board builds are, so that
# their frames on the board's stacks are the board's, and without the host's
# unix macros, which no board compiler defines: embeddedRTPS then takes its
# board paths (its time from the RTOS tick); the stand-ins -O2.
BOARD_FLAGS := -Os -U__unix__ -Uunix -U__unix
CFLAGS = $(COMMON_FLAGS) $(FLAGS_OF_GROUP)
CXXFLAGS = $(COMMON_FLAGS) $(FLAGS_OF_GROUP) -std=gnu++14

STAND_IN_SOURCES := $(addprefix $(PC_TARGET)/src/,board_threads.cpp cmsis_os.cpp sys_arch.cpp \
                      pbuf.cpp network.cpp)

# object name: its group and the source's name (genmros checks that the
# names within a group differ)
object = $(OBJ_DIR)/$(1)_$(basename $(notdir $(2))).o
LIBRARY_OBJS := $(foreach source,$(MROS2_SOURCES),$(call object,lib,$(source)))
STAND_IN_OBJS := $(foreach source,$(STAND_IN_SOURCES),$(call object,pc,$(source)))
APP_OBJS := $(foreach source,$(APP_SOURCES),$(call object,app,$(source)))

all: $(BUILD)/$(PROGRAM)
library: $(LIBRARY_OBJS) $(STAND_IN_OBJS)
app: $(APP_OBJS)
program: $(BUILD)/$(PROGRAM)

$(BUILD)/$(PROGRAM): $(LIBRARY_OBJS) $(STAND_IN_OBJS) $(APP_OBJS)
	$(CXX) $(CPU_FLAGS) -pthread $(SANITIZER_FLAGS) $(LINK_FLAGS) -o $@ $^

# compile_rule(group, source, the group's flags, extra flags)
define compile_rule
$(call object,$(1),$(2)): $(2) $(FLAGS_STAMP) | $(OBJ_DIR)
	$$(if $$(filter %.c,$(2)),$$(CC) $$(CFLAGS),$$(CXX) $$(CXXFLAGS)) $(4) -c $(2) -o $$@
$(call object,$(1),$(2)): FLAGS_OF_GROUP := $(3)
endef
$(foreach source,$(MROS2_SOURCES),$(eval $(call compile_rule,lib,$(source),$(BOARD_FLAGS))))
$(foreach source,$(APP_SOURCES),$(eval $(call compile_rule,app,$(source),$(BOARD_FLAGS),$(APP_FLAGS))))
$(foreach source,$(STAND_IN_SOURCES),$(eval $(call compile_rule,pc,$(source),-O2,\
  -Wall -Wextra -pedantic $(STAND_IN_FLAGS))))

$(OBJ_DIR):
	mkdir -p $@

-include $(wildcard $(OBJ_DIR)/*.d)

.PHONY: all library app program
