#!/usr/bin/env bash
# Serialization benchmark: genmros' headers against roscpp's and against a
# bare memcpy, -O2, each measurement in a process of its own (table.py).
# Also reports the code size each side compiles to. Run by hand:
#   bench/serialization/run.sh [--rounds N] [--seconds S]
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
types=(--type sensor_msgs/Image --type geometry_msgs/PoseStamped --type sensor_msgs/JointState --type std_msgs/String)
# genmros from this checkout, wherever the script is run from.
PYTHONPATH="$here/../.." /usr/bin/python3 -m colcon_mros export --underlay /usr -o "$work/include" "${types[@]}" \
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
PYTHONPATH="$here/../.." /usr/bin/python3 -m colcon_mros export --underlay /usr -o "$work/bounded" "${types[@]}" \
  --storage bounded --options "$here/bounds.options" >/dev/null
g++ "${flags[@]}" -Werror -c -o "$work/bounded_side.o" "$here/mros_side.cpp" -I"$work/bounded" -I"$here"
g++ -o "$work/bench_roscpp" "$work/main.o" "$work/roscpp_side.o" "${libraries[@]}"
g++ -o "$work/bench_genmros" "$work/main.o" "$work/mros_side.o"
g++ -o "$work/bench_memcpy" "$work/main.o" "$work/memcpy_side.o"
g++ -o "$work/bench_bounded" "$work/main.o" "$work/bounded_side.o"
/usr/bin/python3 "$here/table.py" "$work" "$@"
echo
echo "code size (text bytes) of the four types' encode/decode, -O2:"
size "$work/roscpp_side.o" "$work/mros_side.o" "$work/bounded_side.o" | awk 'NR == 1 || /side/ {print "  " $1 "\t" $6}'
