#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Serialization benchmark: genmros' headers against roscpp's and against a
# bare memcpy, -O2, each measurement in a process of its own, in several code
# and heap layouts (table.py).
# Also reports the code size each side compiles to. Run by hand:
#   bench/serialization/run.sh [--rounds N] [--seconds S]
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
types=(--type sensor_msgs/Image --type geometry_msgs/PoseStamped --type sensor_msgs/JointState --type std_msgs/String)
# genmros from this checkout, wherever the script is run from; the message
# packages from the ROS environment (ROS_PACKAGE_PATH, CMAKE_PREFIX_PATH; with
# nothing sourced, Debian's /usr), as testing/ros_paths.py reads it.
PYTHONPATH="$here/../.." /usr/bin/python3 -m colcon_mros mros-v1-export -o "$work/include" "${types[@]}" \
  >/dev/null
flags=(-std=c++11 -O2 -Wall -Wextra -pedantic)
libraries=(-lroscpp_serialization -lrostime -lcpp_common)
g++ "${flags[@]}" -Werror -c -o "$work/main.o" "$here/main.cpp" -I"$here"
g++ "${flags[@]}" -c -o "$work/roscpp_side.o" "$here/roscpp_side.cpp" -I"$here"
g++ "${flags[@]}" -Werror -c -o "$work/mros_side.o" "$here/mros_side.cpp" -I"$work/include" -I"$here"
g++ "${flags[@]}" -Werror -DBENCH_BARE_MEMCPY -c -o "$work/memcpy_side.o" "$here/mros_side.cpp" \
  -I"$work/include" -I"$here"
# Bounded storage: the same instances in heap-free messages, with bounds that
# just fit them (bounds.options).
PYTHONPATH="$here/../.." /usr/bin/python3 -m colcon_mros mros-v1-export -o "$work/bounded" "${types[@]}" \
  --storage bounded --options "$here/bounds.options" >/dev/null
g++ "${flags[@]}" -Werror -c -o "$work/bounded_side.o" "$here/mros_side.cpp" -I"$work/bounded" -I"$here"
# Every side in four code layouts (table.py: layout N is bench_SIDE.N).
for layout in 0 1 2 3; do
  g++ -O2 -DBENCH_CODE_PAD=$((16 * (layout + 1))) -c -o "$work/code_pad.o" "$here/code_pad.cpp"
  g++ -o "$work/bench_roscpp.$layout" "$work/main.o" "$work/code_pad.o" "$work/roscpp_side.o" "${libraries[@]}"
  for side in mros memcpy bounded; do
    executable="bench_$side.$layout"
    g++ -o "$work/${executable/mros/genmros}" "$work/main.o" "$work/code_pad.o" "$work/${side}_side.o"
  done
done
/usr/bin/python3 "$here/table.py" "$work" "$@"
echo
echo "code size (text bytes) of the four types' encode/decode, -O2:"
size "$work/roscpp_side.o" "$work/mros_side.o" "$work/bounded_side.o" | awk 'NR == 1 || /side/ {print "  " $1 "\t" $6}'
