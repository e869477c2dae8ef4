#!/usr/bin/env bash
# Serialization benchmark: genmros' headers against roscpp's, -O2, one run.
# Also reports the code size each side compiles to. Run by hand.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
/usr/bin/python3 -m colcon_mros export --underlay /usr -o "$work/include" \
  --type sensor_msgs/Image --type geometry_msgs/PoseStamped --type sensor_msgs/JointState --type std_msgs/String \
  >/dev/null
flags=(-std=c++11 -O2 -Wall -Wextra -pedantic)
g++ "${flags[@]}" -c -o "$work/roscpp_side.o" "$here/roscpp_side.cpp" -I"$here"
g++ "${flags[@]}" -Werror -c -o "$work/mros_side.o" "$here/mros_side.cpp" -I"$work/include" -I"$here"
g++ "${flags[@]}" -Werror -c -o "$work/main.o" "$here/main.cpp" -I"$here"
g++ -o "$work/bench" "$work"/*.o -lroscpp_serialization -lrostime -lcpp_common
"$work/bench" "${1:-0.5}"
echo
echo "code size (text bytes) of the four types' encode/decode, -O2:"
size "$work/roscpp_side.o" "$work/mros_side.o" | awk 'NR == 1 || /side/ {print "  " $1 "\t" $6}'
