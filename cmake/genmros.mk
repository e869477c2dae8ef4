# SPDX-License-Identifier: BSD-3-Clause
# genmros.mk: mROS message headers for an mROS v1 app built with make.
#
# mROS v1 apps (mros_ws/<app>/Makefile) build with make, not CMake. An app's
# Makefile names its message types and includes this fragment:
#
#   MROS_MSG_TYPES := custom_pubsub/UserTypeTest std_msgs/String
#   MROS_MSG_PATHS := ../msgs        # optional, see below
#   GENMROS_MK := $(shell genmros make-fragment)
#   include $(or $(GENMROS_MK),$(error genmros not found: install colcon-mros))
#
# Before make builds anything, it writes the headers of those types and of
# every type they contain, and the aggregates the mROS library includes
# (message_headers.h, message_class_specialization.h, msg_max_size.h, and
# mros_v1_delivery.h and mros_v1_fit_check.h, which they include), into
# the app's include directory; it writes them again whenever one of the
# .msg/.srv files they come from, or a setting below, changes.
#
#   MROS_MSG_TYPES        pkg/Type ... the app publishes or subscribes (required)
#   MROS_MSG_PATHS        where packages are: catkin source trees (searched for
#                         package.xml) and installed prefixes (with share/<pkg>/msg;
#                         a directory with share/ is one); default: the ROS
#                         environment genmros finds
#   MROS_MSG_INCLUDE_DIR  output directory (default: include, the app's include dir)
#   MROS_MSG_DEFINITION_TEXT  full (default: gencpp's definition texts) or
#                         compact (without comments and blank lines: less flash,
#                         the same MD5 sums)
#   MROS_MSG_FLAGS        further genmros mros-v1-export flags, e.g. the fit check against
#                         the library's settings (one error line per setting too
#                         small): --mros-v1-settings mros_config/mros_usr_config.h
#                         --mros-v1-settings <mros-lib>/mros-src/packet/cimpl/version/kinetic/mros_packet_config.h
#   GENMROS               the genmros command (default: genmros)
#
# Installed next to the CMake module (share/genmros/cmake/); `genmros
# make-fragment` prints where.

GENMROS ?= genmros
MROS_MSG_INCLUDE_DIR ?= include

ifeq ($(strip $(MROS_MSG_TYPES)),)
$(error genmros.mk: MROS_MSG_TYPES names no message type (pkg/Type ...))
endif
ifeq ($(shell command -v $(firstword $(GENMROS)) 2>/dev/null),)
$(error genmros.mk: '$(firstword $(GENMROS))' not found: install colcon-mros or set GENMROS)
endif

# A package path as genmros' --prefix (an installed prefix: it has share/)
# or --workspace (a source tree), by genmros' own rule for package paths.
_mros_msg_path_arg = $(if $(wildcard $(1)/.), \
  $(if $(wildcard $(1)/share/.),--prefix,--workspace) $(1), \
  $(error genmros.mk: MROS_MSG_PATHS: $(1): not a directory: a package path is a \
    source tree of packages or an installed prefix (with share/<pkg>/msg)))

_mros_msg_args := mros-v1-export -o $(MROS_MSG_INCLUDE_DIR) \
  $(addprefix --type ,$(MROS_MSG_TYPES)) \
  $(foreach path,$(MROS_MSG_PATHS),$(call _mros_msg_path_arg,$(path))) \
  $(if $(MROS_MSG_DEFINITION_TEXT),--definition-text $(MROS_MSG_DEFINITION_TEXT)) $(MROS_MSG_FLAGS)

# genmros keeps the run record in this file, a makefile; make remakes an
# included makefile before anything else, so the headers are current before
# the first object is compiled. genmros runs every time and decides from the
# record whether anything changed (a definition, an options file, a setting);
# when nothing did it writes nothing, and make goes on without reading the
# makefiles again.
_mros_msg_record := $(MROS_MSG_INCLUDE_DIR)/.genmros.d
_mros_msg_default_goal := $(.DEFAULT_GOAL)

$(_mros_msg_record): _mros_msg_ask_genmros
	@$(GENMROS) $(_mros_msg_args) --record $@ --quiet

.PHONY: _mros_msg_ask_genmros
include $(_mros_msg_record)

# The app's first target stays make's default goal.
.DEFAULT_GOAL := $(_mros_msg_default_goal)
