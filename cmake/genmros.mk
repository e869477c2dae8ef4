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
# (message_headers.h, message_class_specialization.h, msg_max_size.h), into
# the app's include directory; it writes them again whenever one of the
# .msg/.srv files they come from, or the app's Makefile, changes.
#
#   MROS_MSG_TYPES        pkg/Type ... the app publishes or subscribes (required)
#   MROS_MSG_PATHS        where packages are: catkin source trees (searched for
#                         package.xml) and installed prefixes (with share/<pkg>/msg);
#                         default: the ROS environment genmros finds
#   MROS_MSG_INCLUDE_DIR  output directory (default: include, the app's include dir)
#   MROS_MSG_DEFINITION_TEXT  full (default: gencpp's definition texts) or
#                         compact (without comments and blank lines: less flash,
#                         the same MD5 sums)
#   MROS_MSG_FLAGS        further genmros export flags
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

# A directory with share/ is an installed prefix; any other, a source tree.
_mros_msg_prefixes := $(foreach path,$(MROS_MSG_PATHS),$(if $(wildcard $(path)/share/.),$(path)))
_mros_msg_sources := $(filter-out $(_mros_msg_prefixes),$(MROS_MSG_PATHS))
_mros_msg_args := export -o $(MROS_MSG_INCLUDE_DIR) \
  $(addprefix --type ,$(MROS_MSG_TYPES)) \
  $(addprefix --underlay ,$(_mros_msg_prefixes)) \
  $(addprefix --workspace ,$(_mros_msg_sources)) \
  $(if $(MROS_MSG_DEFINITION_TEXT),--definition-text $(MROS_MSG_DEFINITION_TEXT)) $(MROS_MSG_FLAGS)

# genmros lists in this file the definitions the headers come from, as rules
# whose change remakes it; make remakes an included makefile before anything
# else, so the headers are current before the first object is compiled.
_mros_msg_depfile := $(MROS_MSG_INCLUDE_DIR)/.genmros.d
_mros_msg_default_goal := $(.DEFAULT_GOAL)

$(_mros_msg_depfile): $(firstword $(MAKEFILE_LIST))
	$(GENMROS) $(_mros_msg_args) --depfile $@
	@echo '_mros_msg_made_with := $(_mros_msg_args)' >> $@

include $(_mros_msg_depfile)

# Other types or paths (from make's command line, say) make the headers anew.
ifneq ($(strip $(_mros_msg_made_with)),$(strip $(_mros_msg_args)))
$(_mros_msg_depfile): _mros_msg_arguments_changed
.PHONY: _mros_msg_arguments_changed
endif

# The app's first target stays make's default goal.
.DEFAULT_GOAL := $(_mros_msg_default_goal)
