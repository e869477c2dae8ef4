#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# mros2 footprint benchmark: the flash and RAM std_msgs/String and
# geometry_msgs/Twist cost a Cortex-M4 firmware (arm-none-eabi-g++ -Os
# -mcpu=cortex-m4 -mthumb -mfloat-abi=hard -mfpu=fpv4-sp-d16 -fno-exceptions
# -fno-rtti, --gc-sections, newlib nano), with genmros' headers against the
# hand-written ones mros2 ships ($MROS2_ROOT/mros2_msgs).
# Each firmware (footprint/firmware.cpp) publishes the type and receives it
# through mros2's calls as testing/mros2_runtime defines them (what mros2's
# src/mros2.cpp does, instantiated by a templates.hpp), minus the baseline:
# the same firmware without any message type.
# Run by hand: MROS2_ROOT=<mros2 checkout> bench/mros2/footprint.sh
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
repo="$(cd "$here/../.." && pwd)"
runtime="$repo/testing/mros2_runtime"
if [ ! -f "${MROS2_ROOT:-}/mros2_msgs/std_msgs/msg/string.hpp" ]; then
  echo "$0: needs an mros2 checkout (its hand-written mros2_msgs headers): set MROS2_ROOT" >&2
  exit 2
fi
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

cpu=(-mcpu=cortex-m4 -mthumb -mfloat-abi=hard -mfpu=fpv4-sp-d16)
flags=(-Os -std=gnu++14 -fno-exceptions -fno-rtti -ffunction-sections -fdata-sections)
link=(-Wl,--gc-sections --specs=nano.specs --specs=nosys.specs)

# ROS 2's definitions of the two types (rosidl's, without comments), as a workspace for genmros.
ws="$work/ws"
for package in std_msgs geometry_msgs; do
  mkdir -p "$ws/$package/msg"
  PYTHONPATH="$repo" /usr/bin/python3 -c \
    "import sys; from testing.ros2_messages import PACKAGE_XML; sys.stdout.write(PACKAGE_XML % '$package')" \
    >"$ws/$package/package.xml"
done
echo "string data" >"$ws/std_msgs/msg/String.msg"
printf 'Vector3 linear\nVector3 angular\n' >"$ws/geometry_msgs/msg/Twist.msg"
printf 'float64 x\nfloat64 y\nfloat64 z\n' >"$ws/geometry_msgs/msg/Vector3.msg"

# include dirs: genmros' export with its templates.hpp; the hand-written
# headers with a templates.hpp as mros2's templates_generator.py writes it.
declare -A cpp_type=([string]=std_msgs::msg::String [twist]=geometry_msgs::msg::Twist)
declare -A ros_type=([string]=std_msgs/msg/String [twist]=geometry_msgs/msg/Twist)
declare -A header=([string]=std_msgs/msg/string.hpp [twist]=geometry_msgs/msg/twist.hpp)
declare -A define=([string]=BENCH_STRING [twist]=BENCH_TWIST)
for name in string twist; do
  PYTHONPATH="$repo" /usr/bin/python3 -m colcon_mros mros2-export --workspace "$ws" \
    --publish "${ros_type[$name]}" --subscribe "${ros_type[$name]}" -o "$work/genmros.$name" >/dev/null
  hand="$work/hand.$name"
  mkdir -p "$hand"
  cp -r "$MROS2_ROOT/mros2_msgs/std_msgs" "$MROS2_ROOT/mros2_msgs/geometry_msgs" "$hand/"
  t=${cpp_type[$name]}
  cat >"$hand/templates.hpp" <<TEMPLATES
#include "${header[$name]}"
template mros2::Publisher mros2::Node::create_publisher<$t>(std::string topic_name, int qos);
template void mros2::Publisher::publish($t &msg);
template mros2::Subscriber mros2::Node::create_subscription(std::string topic_name, int qos, void (*fp)($t*));
template void mros2::Subscriber::callback_handler<$t>(void *callee, const rtps::ReaderCacheChange &cacheChange);
TEMPLATES
done
mkdir -p "$work/none"
: >"$work/none/templates.hpp"

build() {  # out include_dir [defines...] -> elf; the compiler's errors on stderr
  local out=$1 include=$2
  shift 2
  arm-none-eabi-g++ "${cpu[@]}" "${flags[@]}" -I"$include" -I"$runtime" "$@" \
    "$here/footprint/firmware.cpp" "$runtime/mros2_runtime_check.cpp" "${link[@]}" -o "$out.elf"
  echo "$out.elf"
}
elf_size() { arm-none-eabi-size "$1" | awk 'NR == 2 {print $1, $2, $3}'; }
cost() {  # elf baseline_elf -> text data bss over the baseline
  read -r t d b <<<"$(elf_size "$1")"
  read -r bt bd bb <<<"$(elf_size "$2")"
  echo "$((t - bt)) $((d - bd)) $((b - bb))"
}
ratio() { awk -v a="$1" -v b="$2" 'BEGIN {printf "%.2fx", a / b}'; }

base=$(build "$work/baseline" "$work/none")
base_iostream=$(build "$work/baseline_iostream" "$work/none" -DBENCH_IOSTREAM)

echo "Bytes a message type adds to a Cortex-M4 firmware that publishes and receives it through mros2's"
echo "calls (testing/mros2_runtime), over the same firmware without a message type; arm-none-eabi-gcc"
echo "$(arm-none-eabi-gcc -dumpversion), -Os, newlib nano, --gc-sections. Flash is text+data, RAM data+bss."
echo
echo "| type | headers | text | data | bss | flash | RAM | genmros / hand-written, flash | text+data+bss |"
echo "|---|---|---:|---:|---:|---:|---:|---:|---:|"
notes=()
for name in string twist; do
  read -r gt gd gb <<<"$(cost "$(build "$work/genmros.$name" "$work/genmros.$name" -D"${define[$name]}")" "$base")"
  if ! hand_elf=$(build "$work/hand.$name" "$work/hand.$name" -D"${define[$name]}" 2>"$work/hand.$name.log"); then
    echo "| ${cpp_type[$name]} | mros2's hand-written | does not build: $(grep -m1 -E 'error|undefined' "$work/hand.$name.log") | | | | | | |"
    continue
  fi
  read -r ht hd hb <<<"$(cost "$hand_elf" "$base")"
  echo "| ${cpp_type[$name]} | mros2's hand-written | $ht | $hd | $hb | $((ht + hd)) | $((hd + hb)) | | |"
  echo "| ${cpp_type[$name]} | genmros | $gt | $gd | $gb | $((gt + gd)) | $((gd + gb)) | $(ratio $((gt + gd)) $((ht + hd))) | $(ratio $((gt + gd + gb)) $((ht + hd + hb))) |"
  if grep -q '<iostream>' "$MROS2_ROOT/mros2_msgs/${header[$name]}"; then
    read -r it id ib <<<"$(cost "$hand_elf" "$base_iostream")"
    echo "| ${cpp_type[$name]} | mros2's hand-written, iostream start-up counted in the baseline | $it | $id | $ib | $((it + id)) | $((id + ib)) | $(ratio $((gt + gd)) $((it + id))) | $(ratio $((gt + gd + gb)) $((it + id + ib))) |"
    notes+=("mros2's ${header[$name]} includes <iostream> (unused): its static start-up object pulls iostream into the firmware unless the firmware has it anyway (the last row: a baseline that includes <iostream>).")
  fi
done
echo
echo "Each firmware also holds the runtime's publish buffers (164 bytes of bss, the same for both header sets); a few bytes of bss move with section alignment."
for note in "${notes[@]}"; do echo "$note"; done
if grep -q 'std::string getTypeName();' "$MROS2_ROOT/mros2_msgs/std_msgs/msg/string.hpp"; then
  echo "mros2's std_msgs/msg/string.hpp declares getTypeName() and never defines it: it builds as long as nothing calls it (nothing does here)."
fi
