#!/usr/bin/env bash
# The main job: on a fresh Debian 12 machine, install what is needed
# (scripts/setup.sh), build test_ws with catkin_make (genmros runs beside
# gencpp/genpy) and the sample firmware for the POSIX target with
# cmake/mros_generate.cmake, start a real rosmaster on a free loopback port
# and run the mROS paper's evaluation both ways against real rospy and
# roscpp nodes. With an mROS v1 checkout (MROS_V1_ROOT=DIR, or
# ../shared/mros_v1 beside this repository) it also runs the evaluation as an
# mROS v1 app on the real library (genmros mros-v1-pc, under qemu-arm) and
# prints both tables. Stops everything it started; exits 0 only if every
# direction delivered the right values.
#
#   scripts/run-evaluation.sh [--messages N] [--build-dir DIR]
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"

"$here/scripts/setup.sh"
exec /usr/bin/python3 "$here/tests/posix_evaluation.py" "$@"
