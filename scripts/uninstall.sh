#!/usr/bin/env bash
# Removes what scripts/setup.sh installed of colcon-mros (not the Debian
# packages, which other software may use): the catkin generator marker in
# /etc/ros/genmsg, then the Python package with its genmros command, CMake
# module and make fragment. catkin builds go on without genmros afterwards.
set -euo pipefail
as_root() { if [ "$(id -u)" = 0 ]; then "$@"; else sudo "$@"; fi; }

marker=/etc/ros/genmsg/genmros
# Only the link setup.sh made: a marker some other install owns stays.
if [ -L "$marker" ] && [[ "$(readlink "$marker")" == */share/genmros/genmsg/genmros ]]; then
  as_root rm -f "$marker"
fi
pip_flags=(--yes)
if /usr/bin/python3 -m pip uninstall --help | grep -q -- --break-system-packages; then
  pip_flags+=(--break-system-packages)
fi
if /usr/bin/python3 -m pip show colcon-mros >/dev/null 2>&1; then
  as_root /usr/bin/python3 -m pip uninstall --quiet "${pip_flags[@]}" colcon-mros
fi
