#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Footprint benchmark: the flash (text+data) and RAM (data+bss) message types
# cost a firmware on each mROS CPU, -Os -fno-builtin -fno-exceptions -fno-rtti -std=gnu++98 (mROS v1's
# flags), --gc-sections.
# Each row is one firmware (start-up, newlib, the API layer in the shape of
# mROS v1's ros.cpp over the library's own api/ros.h, from MROS_V1_ROOT,
# with the PC target's ASP headers for its kernel.h and t_syslog.h, and one
# task that publishes and subscribes one type),
# minus the same firmware without any message type (baseline.cpp).
#   genmros' headers against hand-written v1-style ones (handwritten/), with
#   the library as it is and with genmros' patch set (it passes frame sizes)
#   heap against bounded storage, and the RAM a firmware's buffers take
#   heap with the compact definition text against the full one, and
#   the definition bytes of the Debian message set (definition_text.py)
# Run by hand: MROS_V1_ROOT=<mROS v1 checkout> bench/footprint/run.sh
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
repo="$here/../.."
if [ ! -f "${MROS_V1_ROOT:-}/mros-lib/Makefile.m" ]; then
  echo "$0: needs an mROS v1 checkout (its api/ros.h declares the API): set MROS_V1_ROOT" >&2
  exit 2
fi
mros_src="$MROS_V1_ROOT/mros-lib/mros-src"
ros_h=(-I"$mros_src/api" -I"$mros_src/os/target/os_asp" -I"$repo/colcon_mros/library_tools/mros_v1/pc_target/asp")
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

declare -A cpus=(
  [cortex-m0]="-mcpu=cortex-m0 -mthumb"
  [cortex-m4]="-mcpu=cortex-m4 -mthumb -mfloat-abi=hard -mfpu=fpv4-sp-d16"
  [cortex-a9]="-mcpu=cortex-a9 -marm -mfpu=vfpv3 -mfloat-abi=hard -mno-unaligned-access"
)
cflags=(-Os -fno-builtin -ffunction-sections -fdata-sections)
common=("${cflags[@]}" -fno-exceptions -fno-rtti)
link=(--specs=nosys.specs -Wl,--gc-sections)

genmros() { PYTHONPATH="$repo" /usr/bin/python3 -m colcon_mros "$@" >/dev/null; }
# include dir of genmros' export of one type: heap or bounded storage, full or
# compact definition text; the installed message packages from the ROS
# environment (ROS_PACKAGE_PATH, CMAKE_PREFIX_PATH; with nothing sourced,
# Debian's /usr), as testing/ros_paths.py reads it
export_type() {  # name type storage definition_text
  local flags=(--definition-text "$4")
  [ "$3" = bounded ] && flags+=(--storage bounded --options "$here/bounds.options")
  genmros mros-v1-export --workspace "$repo/test_ws" --workspace "$here/msgs" --type "$2" \
    -o "$work/$1" "${flags[@]}"
  echo "$work/$1"
}

elf_size() {  # elf -> "text data bss"
  arm-none-eabi-size "$1" | awk 'NR == 2 {print $1, $2, $3}'
}

build() {  # cpu output include_dir type header [compile flags] -> elf
  local cpu=$1 out=$2 include=$3 type=$4 header=$5 flags=${6:-}
  # shellcheck disable=SC2086
  arm-none-eabi-gcc ${cpus[$cpu]} "${cflags[@]}" -std=c99 -c "$here/library.c" -o "$out.library.o"
  arm-none-eabi-gcc ${cpus[$cpu]} "${cflags[@]}" -std=c99 -c "$here/sink.c" -o "$out.sink.o"
  if [ "$type" = none ]; then
    arm-none-eabi-g++ ${cpus[$cpu]} "${common[@]}" -std=gnu++98 -I"$here" "$here/baseline.cpp" \
      "$out.library.o" "$out.sink.o" "${link[@]}" -o "$out.elf"
  else
    # The API layer includes ros.h and message_headers.h as ros.cpp does, but not the
    # samples' settings, whose 512-byte header buffers the fit check would refuse
    # JointState's and Odometry's definition texts with: the bytes are what is measured here.
    arm-none-eabi-g++ ${cpus[$cpu]} "${common[@]}" -std=gnu++98 -Wno-psabi -I"$include" -I"$here" \
      -DMROS_SKIP_FIT_CHECK $flags -DBENCH_TYPE="$type" -DBENCH_HEADER="<$header>" "${ros_h[@]}" \
      "$here/api_layer.cpp" "$here/task.cpp" \
      "$out.library.o" "$out.sink.o" "${link[@]}" -o "$out.elf"
  fi
  echo "$out.elf"
}

# name  ROS type  C++ type  header
types=(
  "personal mros_test/PersonalData mros_test::PersonalData mros_test/PersonalData.h"
  "usertype bench_msgs/UserTypeTest bench_msgs::UserTypeTest bench_msgs/UserTypeTest.h"
  "joint sensor_msgs/JointState sensor_msgs::JointState sensor_msgs/JointState.h"
  "odometry nav_msgs/Odometry nav_msgs::Odometry nav_msgs/Odometry.h"
)
declare -A handwritten=([personal]="$here/handwritten/mros_test" [usertype]="$here/handwritten/bench_msgs")

declare -A include
for entry in "${types[@]}"; do
  read -r name ros_type _ _ <<<"$entry"
  include[$name.heap]=$(export_type "$name.heap" "$ros_type" heap full)
  include[$name.compact]=$(export_type "$name.compact" "$ros_type" heap compact)
  include[$name.bounded]=$(export_type "$name.bounded" "$ros_type" bounded full)
done

cost() {  # elf baseline_elf -> flash (text+data), RAM (data+bss), text+data+bss over the baseline
  read -r t d b <<<"$(elf_size "$1")"
  read -r bt bd bb <<<"$(elf_size "$2")"
  echo "$((t + d - bt - bd)) $((d + b - bd - bb)) $((t + d + b - bt - bd - bb))"
}
ratio() { awk -v a="$1" -v b="$2" 'BEGIN {printf "%.2fx", a / b}'; }

echo "Bytes a message type adds to a firmware over the baseline firmware without one: flash (text+data)"
echo "and RAM (data+bss), each genmros form beside hand-written v1 headers, and the ratio of text+data+bss."
echo "\"as is\": the library passes delivery no frame size, so on-board delivery keeps a table of the frames"
echo "published on the board (260 bytes of RAM once per firmware); \"patched\": genmros' patch set, whose"
echo "library passes the size (no table). A message of up to 128 bytes is delivered from the subscriber"
echo "task's stack, a larger one from static storage (RAM)."
echo
echo "| CPU | type | hand-written flash | RAM | genmros as is flash | RAM | as is / hand-written | genmros patched flash | RAM | patched / hand-written | bounded, patched flash | RAM | compact text, patched flash | compact / full flash |"
echo "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
for cpu in cortex-m0 cortex-m4 cortex-a9; do
  base=$(build "$cpu" "$work/$cpu.baseline" "" none "")
  for entry in "${types[@]}"; do
    read -r name _ cpp_type header <<<"$entry"
    patched=-DMROS_LIBRARY_PASSES_FRAME_SIZE
    read -r af ar at <<<"$(cost "$(build "$cpu" "$work/$cpu.$name.heap" "${include[$name.heap]}" "$cpp_type" "$header")" "$base")"
    read -r pf pr pt <<<"$(cost "$(build "$cpu" "$work/$cpu.$name.patched" "${include[$name.heap]}" "$cpp_type" "$header" "$patched")" "$base")"
    read -r bf br _ <<<"$(cost "$(build "$cpu" "$work/$cpu.$name.bounded" "${include[$name.bounded]}" "$cpp_type" "$header" "$patched")" "$base")"
    read -r cf _ _ <<<"$(cost "$(build "$cpu" "$work/$cpu.$name.compact" "${include[$name.compact]}" "$cpp_type" "$header" "$patched")" "$base")"
    if [ -n "${handwritten[$name]:-}" ]; then
      read -r hf hr ht <<<"$(cost "$(build "$cpu" "$work/$cpu.$name.hand" "${handwritten[$name]}" "$cpp_type" "$header")" "$base")"
      as_is_ratio=$(ratio "$at" "$ht")
      patched_ratio=$(ratio "$pt" "$ht")
    else
      hf="-"; hr="-"; as_is_ratio="-"; patched_ratio="-"
    fi
    echo "| $cpu | $cpp_type | $hf | $hr | $af | $ar | $as_is_ratio | $pf | $pr | $patched_ratio | $bf | $br | $cf | $(ratio "$cf" "$pf") |"
  done
done

echo
echo "RAM for a firmware's buffers (bytes): the publish block (PUB_MSG_MAX_SIZE + 4) and one message object,"
echo "which for a message over 128 bytes is also the static storage delivery keeps a received message in"
echo "(counted in the RAM of the table above). Heap storage also takes what its strings and arrays hold"
echo "from the heap, at run time."
echo
echo "| type | heap: PUB_MSG_MAX_SIZE | heap: sizeof message | bounded: PUB_MSG_MAX_SIZE | bounded: sizeof message |"
echo "|---|---:|---:|---:|---:|"
for entry in "${types[@]}"; do
  read -r name _ cpp_type header <<<"$entry"
  row="| $cpp_type"
  for storage in heap bounded; do
    probe="$work/$name.$storage.probe.cpp"
    printf '#include <%s>\n#include <msg_max_size.h>\nunsigned max_size = PUB_MSG_MAX_SIZE;\nunsigned object_size = sizeof(%s);\n' \
      "$header" "$cpp_type" > "$probe"
    arm-none-eabi-g++ ${cpus[cortex-m4]} -std=gnu++98 -Wno-psabi -c -I"${include[$name.$storage]}" "$probe" -o "$probe.o"
    read -r max object <<<"$(arm-none-eabi-objdump -s -j .data "$probe.o" | awk '/^ 0000/ {print $2, $3}')"
    le() { echo $((16#${1:6:2}${1:4:2}${1:2:2}${1:0:2})); }
    row="$row | $(le "$max") | $(le "$object")"
  done
  echo "$row |"
done
echo
echo "(bounded storage with bench/footprint/bounds.options; heap PUB_MSG_MAX_SIZE counts a type without a maximum as the 1024-byte budget)"
echo
PYTHONPATH="$repo" /usr/bin/python3 "$here/definition_text.py"
