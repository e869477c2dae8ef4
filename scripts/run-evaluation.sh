#!/usr/bin/env bash
# The main job: on a fresh Debian 12 machine, install what is needed
# (scripts/setup.sh), build test_ws with catkin_make (genmros runs beside
# gencpp/genpy), build the paper's evaluation app with the real mROS v1
# library on the PC target (genmros mros-v1-pc, run under qemu-arm), start a
# real rosmaster on a free loopback port and run the mROS paper's evaluation
# in every direction against real rospy and roscpp nodes, on-board delivery
# included. The mROS v1 checkout is MROS_V1_ROOT, default ../shared/mros_v1
# beside this repository. Stops everything it started; exits 0 only if every
# direction delivered the right values.
#
#   scripts/run-evaluation.sh [--messages N] [--build-dir DIR]   (evaluation/run.py)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"

"$here/scripts/setup.sh" --tests
export MROS_V1_ROOT="${MROS_V1_ROOT:-$(dirname "$here")/shared/mros_v1}"
exec /usr/bin/python3 "$here/evaluation/run.py" "$@"
