#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# What genmros' patch set for the mROS v1 library (colcon_mros/library_tools/mros_v1/patches)
# costs in code: each C source of the library a patch changes, compiled as
# the library's own build compiles it for the board (-Os, the board's CPU),
# as it is and with the patches applied (genmros mros-v1-harden on a copy),
# for Cortex-M0, M4 and A9; text+data+bss of each object and the total. The
# RTOS and lwIP declarations are the PC target's stand-ins and
# bench/real_mros/board_only, as in bench/real_mros/run.sh. ros.cpp's change
# (publish) is template code, compiled into each app per published type.
#   bench/hardening/cost.sh MROS_CHECKOUT
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
repo="$(cd "$here/../.." && pwd)"
[ $# = 1 ] || { echo "usage: $0 MROS_CHECKOUT" >&2; exit 2; }
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

mkdir -p "$work/as_is" "$work/hardened"
cp -r "$1/mros-lib" "$work/as_is/"
cp -r "$1/mros-lib" "$work/hardened/"
(cd "$repo" && /usr/bin/python3 -m colcon_mros mros-v1-harden --mros-v1-root "$work/hardened" >/dev/null)

target="$repo/colcon_mros/library_tools/mros_v1/pc_target"
declare -A cpus=(
  [cortex-m0]="-mcpu=cortex-m0 -mthumb"
  [cortex-m4]="-mcpu=cortex-m4 -mthumb -mfloat-abi=hard -mfpu=fpv4-sp-d16"
  [cortex-a9]="-mcpu=cortex-a9 -marm -mfpu=vfpv3 -mfloat-abi=hard -mno-unaligned-access"
)
# diff exits 1 where the trees differ, as they do.
changed=$(cd "$work/hardened" && { diff -rq "$work/as_is/mros-lib" mros-lib || true; } |
          sed -n 's/^Files .* and \(.*\) differ$/\1/p' | grep '\.c$' | sort)

size_of() {  # tree cpu source -> text+data+bss
  local tree=$1 cpu=$2 source=$3 src="$1/mros-lib/mros-src" includes=() dir
  rm -f "$work/object.o"
  for dir in inc api config config/os/target/os_asp protocol/cimpl node/cimpl topic/cimpl os/target/os_asp \
      comm/cimpl/target/lwip comm/cimpl packet/cimpl packet/template/version/kinetic \
      packet/cimpl/version/kinetic transfer/cimpl; do
    includes+=(-I"$src/$dir")
  done
  # shellcheck disable=SC2086
  # newlib leaves fd_set and struct timeval to the socket library (lwIP's,
  # here board_only's); the board's headers bring NULL, which a source uses
  # without <stddef.h>.
  arm-none-eabi-gcc -c -Os -std=gnu99 -ffunction-sections -fdata-sections -fno-builtin ${cpus[$cpu]} \
      -D__USE_W32_SOCKETS -include stddef.h \
      -I"$target/asp" -I"$here/../real_mros/board_only" "${includes[@]}" "$tree/$source" \
      -o "$work/object.o" 2>"$work/compile.log" || { cat "$work/compile.log" >&2; exit 1; }
  arm-none-eabi-size "$work/object.o" | awk 'NR == 2 { print $1 + $2 + $3 }'
}

echo "Code bytes (text+data+bss, -Os) of the library's C sources the patch set changes"
echo
echo "| CPU | source | as it is | hardened | added |"
echo "|---|---|---:|---:|---:|"
for cpu in cortex-m0 cortex-m4 cortex-a9; do
  total_as_is=0 total_hardened=0
  for source in $changed; do
    as_is=$(size_of "$work/as_is" "$cpu" "$source")
    hardened=$(size_of "$work/hardened" "$cpu" "$source")
    total_as_is=$((total_as_is + as_is)) total_hardened=$((total_hardened + hardened))
    echo "| $cpu | $(basename "$source") | $as_is | $hardened | $((hardened - as_is)) |"
  done
  echo "| $cpu | **all** | $total_as_is | $total_hardened | $((total_hardened - total_as_is)) |"
done
