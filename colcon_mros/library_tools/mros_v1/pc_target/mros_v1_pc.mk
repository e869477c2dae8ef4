# SPDX-License-Identifier: BSD-3-Clause
# mros_v1_pc.mk: an unmodified mROS v1 app and library, built for a PC.
#
# `genmros mros-v1-pc APP_DIR` runs this with the variables below, read
# from the app's Makefile, app.json and app.cfg; it has also written the
# kernel configuration (kernel_cfg.h/.c) from app.cfg into $(BUILD)/cfg.
#
#   MROS_ROOT     the mROS v1 checkout (mros-lib/ and mros_ws/)
#   APP_NAME      the program's name
#   APP_DIRS      the app's source directories (its Makefile's APPLDIR)
#   APP_OBJS      its objects (APPLNAME.o, APPL_COBJS, APPL_CXXOBJS)
#   APP_CXXFLAGS  its extra C++ flags (APPL_CXXFLAGS)
#   BOARD_C_OPTIMIZATION, BOARD_CXX_OPTIMIZATION  the optimization its
#                 Makefile gives C and C++ on the board (DEBUG,
#                 OMIT_OPTIMIZATION), for the library's and the app's code
#   TARGET        arm: 32-bit ARM Linux (the board's ISA, static, run with
#                 qemu-arm); native: this PC
#   BUILD         the output directory
#   SANITIZER_FLAGS  added to every compile and the link (genmros --sanitize)
#   FLAGS_STAMP   a file genmros rewrites when the flags change: every object
#                 depends on it
#   FIT_CHECK_FLAGS  -DMROS_SKIP_FIT_CHECK with genmros --no-fit-check, so that
#                 ros.cpp builds even where mros_v1_fit_check.h finds a misfit
#   MROS_MSG_TYPES, MROS_MSG_PATHS, MROS_MSG_DEFINITION_TEXT, MROS_MSG_FLAGS,
#   GENMROS, GENMROS_MK: the message headers,
#                 written into $(BUILD)/include by genmros' make fragment
#
# The library's own Makefile.m lists its sources and include directories.
# The app's include/ (the old generator's headers) is not used. Goals, one
# step each: library (mros-lib with the app's headers and configuration,
# and the PC target's stand-ins), app (the app's objects and its kernel
# configuration), program (the link); all is the three.

PC_TARGET := $(patsubst %/,%,$(dir $(lastword $(MAKEFILE_LIST))))

all: $(BUILD)/$(APP_NAME)
program: $(BUILD)/$(APP_NAME)

MROS_DIR := $(MROS_ROOT)/mros-lib
include $(MROS_DIR)/Makefile.m

MROS_MSG_INCLUDE_DIR := $(BUILD)/include
include $(GENMROS_MK)

# On arm, tasks run on the board's stack sizes (asp/task_stacks.c) and the
# host C library on the host stack: the link wraps what host_libc/host_libc.c
# defines as __wrap_NAME.
ifeq ($(TARGET),arm)
CROSS := arm-linux-gnueabihf-
CPU_FLAGS := -mcpu=cortex-a9 -marm -mfpu=vfpv3 -mfloat-abi=hard -mno-unaligned-access
LINK_FLAGS := -static
HOST_LIBC_OBJS := host_libc.o
else ifeq ($(TARGET),native)
CROSS :=
CPU_FLAGS :=
LINK_FLAGS :=
HOST_LIBC_OBJS :=
else
$(error mros_v1_pc.mk: TARGET is '$(TARGET)', not arm or native)
endif
CC := $(CROSS)gcc
CXX := $(CROSS)g++
NM := $(CROSS)nm

OBJ_DIR := $(BUILD)/obj
ifneq ($(HOST_LIBC_OBJS),)
HOST_LIBC_WRAP := $(OBJ_DIR)/host_libc.wrap
LINK_FLAGS += -Wl,@$(HOST_LIBC_WRAP)
endif
PC_SOURCE_DIRS := $(PC_TARGET)/asp $(PC_TARGET)/lwip $(PC_TARGET)/mbed $(PC_TARGET)/host_libc \
                  $(PC_TARGET)/config
# The app's sources first: its mros_config/ replaces the library's config/.
VPATH := $(APP_DIRS) $(BUILD)/cfg $(VPATH) $(PC_SOURCE_DIRS)

# genmros' headers first, then the PC's mros_sys_config.h before the app's
# (it includes the app's and replaces the board's addresses and ports).
INCLUDES := -I$(BUILD)/include -I$(PC_TARGET)/config $(addprefix -I,$(APP_DIRS)) \
            $(MROS_INCLUDE_PATHS) -I$(BUILD)/cfg -I$(PC_TARGET)/asp -I$(PC_TARGET)/lwip \
            -I$(PC_TARGET)/mbed
COMMON_FLAGS := $(CPU_FLAGS) -g -pthread -MMD -MP $(SANITIZER_FLAGS) $(FIT_CHECK_FLAGS) \
                $(CDEFS) $(INCLUDES)
# The library and the app as the board's build optimizes them, so that their
# frames on the board's task stacks are the board's; the stand-ins with -O2.
C_OPTIMIZATION = $(BOARD_C_OPTIMIZATION)
CXX_OPTIMIZATION = $(BOARD_CXX_OPTIMIZATION)
CFLAGS = $(COMMON_FLAGS) $(C_OPTIMIZATION)
# mROS v1's flags for C++ (Makefile.mbd), and the app's own.
CXXFLAGS = $(COMMON_FLAGS) $(CXX_OPTIMIZATION) -std=gnu++98 -fno-rtti -fno-exceptions \
           -fno-builtin $(APP_CXXFLAGS)

PC_OBJS := kernel.o kernel_scheduler.o kernel_tasks.o kernel_semaphores.o kernel_timers.o syslog.o \
           task_stacks.o lwip.o ros_environment.o mbed.o $(HOST_LIBC_OBJS)
$(addprefix $(OBJ_DIR)/,$(PC_OBJS)): C_OPTIMIZATION := -O2
$(addprefix $(OBJ_DIR)/,$(PC_OBJS)): CXX_OPTIMIZATION := -O2
LIBRARY_OBJS := $(addprefix $(OBJ_DIR)/,$(MROS_CXX_OBJ) $(MROS_C_OBJ) $(PC_OBJS))
APP_ONLY_OBJS := $(addprefix $(OBJ_DIR)/,$(APP_OBJS) kernel_cfg.o)

library: $(LIBRARY_OBJS)
app: $(APP_ONLY_OBJS)

$(BUILD)/$(APP_NAME): $(LIBRARY_OBJS) $(APP_ONLY_OBJS) $(HOST_LIBC_WRAP)
	$(CXX) $(CPU_FLAGS) -pthread $(SANITIZER_FLAGS) $(LINK_FLAGS) -o $@ $(LIBRARY_OBJS) $(APP_ONLY_OBJS)

# --wrap=NAME for each __wrap_NAME host_libc.o defines.
$(HOST_LIBC_WRAP): $(OBJ_DIR)/host_libc.o
	$(NM) --defined-only $< | sed -n 's/^.* T __wrap_\(.*\)$$/--wrap=\1/p' > $@

$(OBJ_DIR)/%.o: %.c $(FLAGS_STAMP) | $(OBJ_DIR)
	$(CC) $(CFLAGS) -c $< -o $@

$(OBJ_DIR)/%.o: %.cpp $(FLAGS_STAMP) | $(OBJ_DIR)
	$(CXX) $(CXXFLAGS) -c $< -o $@

# The lwIP stand-in's host calls are lambdas.
$(OBJ_DIR)/lwip.o: CXXFLAGS += -std=gnu++11

$(OBJ_DIR):
	mkdir -p $@

-include $(wildcard $(OBJ_DIR)/*.d)

.PHONY: all library app program
