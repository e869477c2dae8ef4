#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Removes colcon-mros (not the Debian packages it needs, which other software
# may use): the Debian package python3-colcon-mros scripts/setup.sh built and
# installed, with the genmros command, the catkin generator marker, the CMake
# module and make fragment, and colcon-mros, the package's name until 0.1.0
# (now its transitional package), with what is left of it. catkin and colcon
# builds go on without genmros afterwards.
# --legacy-only removes only what an earlier setup.sh installed with pip (a
# copy in /usr/local and a link in /etc/ros/genmsg); both are always removed.
set -euo pipefail
as_root() { if [ "$(id -u)" = 0 ]; then "$@"; else sudo "$@"; fi; }

marker=/etc/ros/genmsg/genmros
# Only the link an earlier setup.sh made: a marker some other install owns stays.
if [ -L "$marker" ] && [[ "$(readlink "$marker")" == */share/genmros/genmsg/genmros ]]; then
  as_root rm -f "$marker"
fi
location=$(/usr/bin/python3 -m pip show colcon-mros 2>/dev/null | sed -n 's/^Location: //p' || true)
if [[ "$location" == /usr/local/* ]]; then
  pip_flags=(--quiet --yes)
  if /usr/bin/python3 -m pip uninstall --help | grep -q -- --break-system-packages; then
    pip_flags+=(--break-system-packages)
  fi
  as_root /usr/bin/python3 -m pip uninstall "${pip_flags[@]}" colcon-mros
fi

if [ "${1:-}" = --legacy-only ]; then
  exit 0
fi
# Each one dpkg knows, installed or with its configuration files left.
known=()
for package in python3-colcon-mros colcon-mros; do
  status=$(dpkg-query -W -f='${Status}' "$package" 2>/dev/null || true)
  if [ -n "$status" ] && [[ "$status" != *not-installed ]]; then
    known+=("$package")
  fi
done
if [ ${#known[@]} -gt 0 ]; then
  as_root env DEBIAN_FRONTEND=noninteractive apt-get purge -y -qq "${known[@]}" >/dev/null
fi
