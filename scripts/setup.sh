#!/usr/bin/env bash
# Installs what genmros needs on Debian 12 and installs the project itself
# into Debian's /usr/bin/python3, the interpreter that can import genmsg and
# that catkin and colcon run. Idempotent; needs root (or sudo).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
as_root() { if [ "$(id -u)" = 0 ]; then "$@"; else sudo "$@"; fi; }

packages=$(grep -v '^#' "$here/scripts/debian-packages.txt" | tr '\n' ' ')
missing=$(dpkg-query -W -f='${Package} ${Status}\n' $packages 2>/dev/null \
          | awk '$NF != "installed" {print $1}' || true)
if [ -n "$missing" ] || ! dpkg-query -W $packages >/dev/null 2>&1; then
  as_root apt-get update -qq
  as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends $packages
fi

# --no-deps: every dependency comes from Debian (genmsg is not on PyPI, and
# empy 4 from PyPI would break catkin). --break-system-packages: the project
# must live in Debian's interpreter for catkin and colcon to find it (pip
# before 23 has no such flag and needs none). Built from a copy, so the
# source tree gets no build/ or *.egg-info.
pip_flags=(--quiet --no-deps --no-build-isolation --force-reinstall)
pip_help=$(/usr/bin/python3 -m pip install --help)
for flag in --break-system-packages --root-user-action=ignore; do
  if grep -q -- "${flag%%=*}" <<<"$pip_help"; then pip_flags+=("$flag"); fi
done
source_copy=$(mktemp -d)
trap 'rm -rf "$source_copy"' EXIT
tar -C "$here" --exclude=.git --exclude=build --exclude='*.egg-info' -cf - . | tar -C "$source_copy" -xf -
as_root /usr/bin/python3 -m pip install "${pip_flags[@]}" "$source_copy"

# --- catkin generator registration (issue 3) ---------------------------------
# genmsg runs every generator named by a file in /etc/ros/genmsg (gencpp, genpy
# come from Debian) or in a catkin workspace; pip cannot write to /etc, so the
# marker that pip installed with the CMake files is linked there. Remove the
# link to unregister genmros (or set ROS_LANG_DISABLE=genmros for one build).
# The installed package says where pip put the marker (sysconfig's data path
# is not it where pip installs under /usr/local while Python's prefix is
# /usr, as on Ubuntu 20.04). Run from / so the source tree is not imported.
cmake_dir=$(cd / && /usr/bin/python3 -m colcon_mros cmake-dir)
marker="$(dirname "$cmake_dir")/genmsg/genmros"
[ -f "$marker" ] || { echo "setup.sh: the installed marker $marker is missing" >&2; exit 1; }
as_root mkdir -p /etc/ros/genmsg
as_root ln -sfn "$marker" /etc/ros/genmsg/genmros
