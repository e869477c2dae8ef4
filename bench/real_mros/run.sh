#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# genmros' headers in the real mROS v1 library, as a new user would try them:
# export the types of the sample apps custom_pubsub, string_pubsub and
# image_publisher, put the export in place of each app's include/, and
# compile the real mros-lib/mros-src/api/ros.cpp and the apps' app.cpp with
# the flags of mROS v1's Makefiles (-std=gnu++98 -fno-rtti -fno-exceptions
# -fno-builtin -Os, GR-PEACH's Cortex-A9, and a Cortex-M4). The RTOS and
# mbed headers are the mROS v1 PC target's stand-ins, lwIP's types are
# declared in board_only/ (see its README); everything else is the
# checkout's. Prints each compile's warnings from genmros' headers (none is
# the expectation; the apps' own warnings are counted, not shown) and the
# text+data+bss of ros.o and app.o with the headers mROS ships and with
# genmros'. Where the sample's own settings are too small for its types,
# genmros' fit check refuses ros.cpp's compile: the refusal is printed, and
# the size measured with -DMROS_SKIP_FIT_CHECK. Nothing is linked.
#   bench/real_mros/run.sh MROS_CHECKOUT   (a work tree, or a git dir of mROS-base/mROS)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
repo="$here/../.."
[ $# = 1 ] || { echo "usage: $0 MROS_CHECKOUT" >&2; exit 2; }
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

# The parts of mROS used here, from a work tree or straight from git objects.
mros="$work/mros"
if [ -d "$1/mros-lib" ]; then
  mros="$(cd "$1" && pwd)"
else
  git --git-dir="$1" ls-tree -r --name-only HEAD mros-lib/mros-src mros-lib/mros-msgs mros_ws \
      ros_catkin_ws/src/custom_pubsub |
    while read -r path; do
      mkdir -p "$mros/$(dirname "$path")"
      git --git-dir="$1" show "HEAD:$path" >"$mros/$path" 2>/dev/null || true
    done
fi

src="$mros/mros-lib/mros-src"
target="$repo/colcon_mros/library_tools/mros_v1/pc_target"
includes=(-I"$target/asp" -I"$target/mbed" -I"$here/board_only")
for dir in inc api protocol/cimpl node/cimpl topic/cimpl os/target/os_asp comm/cimpl/target/lwip \
    comm/cimpl packet/cimpl packet/template/version/kinetic packet/cimpl/version/kinetic transfer/cimpl; do
  includes+=(-I"$src/$dir")
done
flags=(-c -Os -std=gnu++98 -fno-rtti -fno-exceptions -fno-builtin -ffunction-sections -fdata-sections
       -Wall -Wextra -Wno-unused-parameter -Wno-missing-field-initializers)
declare -A cpus=(
  [cortex-a9]="-mcpu=cortex-a9 -marm -mfpu=vfpv3 -mfloat-abi=hard -mno-unaligned-access"
  [cortex-m4]="-mcpu=cortex-m4 -mthumb -mfloat-abi=hard -mfpu=fpv4-sp-d16"
)

# app  genmros mros-v1-export arguments  whether app.cpp builds on the stubs (image_publisher needs the camera library)
apps=(
  "custom_pubsub --workspace $mros/ros_catkin_ws --type custom_pubsub/UserTypeTest yes"
  "string_pubsub --type std_msgs/String yes"
  "image_publisher --type sensor_msgs/Image no"
)

compile() {  # cpu headers app source object -> prints "size warnings-from-genmros other-warnings fit-check"
  local cpu=$1 headers=$2 app=$3 source=$4 object=$5 log="$5.log" include fit_check=ran
  if [ "$headers" = shipped ]; then
    include=(-I"$mros/mros_ws/$app/include" -I"$mros/mros-lib/mros-msgs")
  else
    include=(-I"$work/export/$app")
  fi
  local command=(arm-none-eabi-g++ ${cpus[$cpu]} "${flags[@]}" "${includes[@]}" "${include[@]}"
    -I"$work/cfg/$app" -I"$mros/mros_ws/$app" -I"$mros/mros_ws/$app/mros_config"
    -I"$mros/mros_ws/$app/mros_config/os/target/os_asp" "$source" -o "$object")
  if ! "${command[@]}" 2>"$log"; then
    # The sample's own settings too small for its types: the fit check's
    # refusal is the expected result; the size is measured without it.
    if grep -q 'mros_v1_fit_check.h:[0-9]*:[0-9]*: error: #error' "$log"; then
      grep -o '#error "[^"]*"' "$log" | sort -u | sed "s/^/refused by the fit check ($app, $cpu): /" >&2
      fit_check=refused
    fi
    if [ "$fit_check" = ran ] || ! "${command[@]}" -DMROS_SKIP_FIT_CHECK 2>"$log"; then
      echo "compile failed: $app $headers $cpu $(basename "$source")" >&2
      cat "$log" >&2
      exit 1
    fi
  fi
  if [ "$headers" = genmros ] && grep -q "^$work/export/.*warning" "$log"; then
    grep "^$work/export/.*warning" "$log" | sed "s|$work/export/||" >&2
  fi
  echo "$(arm-none-eabi-size "$object" | awk 'NR == 2 {print $4}') $(grep -c "^$work/export/.*warning" "$log" || true) $(grep -v "^$work/export/" "$log" | grep -c "warning" || true) $fit_check"
}

echo "text+data+bss (bytes) of the real ros.cpp and app.cpp, -Os, mROS v1's flags;"
echo "warnings: from genmros' headers / from mROS' own code and the apps"
echo
echo "| CPU | app | file | shipped headers | genmros | genmros / shipped | warnings shipped | warnings genmros |"
echo "|---|---|---|---:|---:|---:|---:|---:|"
for entry in "${apps[@]}"; do
  # shellcheck disable=SC2086
  set -- $entry
  app=$1
  builds_app=${!#}
  arguments=("${@:2:$#-2}")
  PYTHONPATH="$repo" /usr/bin/python3 -m colcon_mros mros-v1-export "${arguments[@]}" -o "$work/export/$app" >/dev/null
  # The task IDs ros.cpp names (kernel_cfg.h), from the app's app.cfg as the
  # PC target makes them; from the library's own mros.cfg where the app's
  # includes board libraries the target does not have (image_publisher's camera).
  PYTHONPATH="$repo" /usr/bin/python3 -c 'import sys
from colcon_mros.errors import GenmrosError
from colcon_mros.library_tools.mros_v1.pc_target.asp_cfg import read_config, write_kernel_config
app_cfg, mros_lib, target_cfg, output = sys.argv[1:]
try:
    config = read_config(app_cfg, [mros_lib, target_cfg])
except GenmrosError:
    config = read_config(mros_lib + "/mros.cfg", [target_cfg])
write_kernel_config(config, output)' \
    "$mros/mros_ws/$app/app.cfg" "$mros/mros-lib" "$target/cfg/asp" "$work/cfg/$app"
  sources=("$src/api/ros.cpp")
  [ "$builds_app" = yes ] && sources+=("$mros/mros_ws/$app/app.cpp")
  for cpu in cortex-a9 cortex-m4; do
    for source in "${sources[@]}"; do
      name=$(basename "$source" .cpp)
      read -r shipped _ shipped_other _ <<<"$(compile "$cpu" shipped "$app" "$source" "$work/$app.$cpu.$name.shipped.o")"
      read -r ours ours_own ours_other fit_check <<<"$(compile "$cpu" genmros "$app" "$source" "$work/$app.$cpu.$name.genmros.o")"
      ratio=$(awk -v a="$ours" -v b="$shipped" 'BEGIN {printf "%.2fx", a / b}')
      [ "$fit_check" = refused ] && ours="$ours (fit check skipped)"
      echo "| $cpu | $app | $name.o | $shipped | $ours | $ratio | 0 / $shipped_other | $ours_own / $ours_other |"
    done
  done
done
