#!/usr/bin/env bash
# miniRT speed on the host: every shared valid scene at 1920x1080 on 2
# threads (--threads 2), median of N interleaved runs of minrt's --stats
# (parse + BVH + render, the image kept in memory and written to /dev/null's
# neighbour), plus the CPU seconds of one single-thread run, which machine
# load does not inflate. The issue's target: the largest file
# (room_test3.rt) under 0.5 s.
# Usage: bench/host/minirt_speed.sh [--runs N] [--size WxH] [--shared DIR]
. "$(dirname "$0")/../../scripts/help.sh"
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
shared=$root/../shared
runs=5
size=1920x1080
while [ $# -gt 0 ]; do
  case $1 in
    --runs) runs=$2; shift 2 ;;
    --size) size=$2; shift 2 ;;
    --shared) shared=$2; shift 2 ;;
    *) echo "minirt_speed.sh: error: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
done
minrt=$root/build/release/host/minrt
[ -x "$minrt" ] || { echo "minirt_speed.sh: error: $minrt not built (run scripts/test.sh first)" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo "cpu: $(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -1), $(nproc) cores, load $(cut -d' ' -f1 /proc/loadavg)"
seconds_of() { sed -n 's/.*parse \([0-9.]*\) s, BVH \([0-9.]*\) s, render \([0-9.]*\) s.*/\1 \2 \3/p' | awk '{print $1 + $2 + $3}'; }
median() { sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
scenes=("$shared"/formats/minirt/valid/*.rt)
declare -A wall
for ((r = 0; r < runs; r++)); do  # interleaved: every scene once per round
  for s in "${scenes[@]}"; do
    n=$(basename "$s" .rt)
    t=$("$minrt" "$s" --size "$size" --threads 2 --stats -o "$work/img.ppm" 2>&1 | seconds_of)
    wall[$n]="${wall[$n]:-} $t"
  done
done
printf "%-22s %8s %10s %8s\n" scene bytes "2 threads" "1 cpu"
for s in "${scenes[@]}"; do
  n=$(basename "$s" .rt)
  m=$(echo "${wall[$n]}" | tr ' ' '\n' | grep . | median)
  cpu=$( { /usr/bin/time -f "%U %S" "$minrt" "$s" --size "$size" --threads 1 -o "$work/img.ppm" ; } 2>&1 | tail -1 | awk '{print $1 + $2}')
  printf "%-22s %8d %9.3fs %7.2fs\n" "$n.rt" "$(stat -c %s "$s")" "$m" "$cpu"
done
