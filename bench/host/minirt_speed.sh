#!/usr/bin/env bash
# miniRT speed on the host: every shared valid scene at 1920x1080 on 2
# threads (--threads 2), median of N interleaved runs of minrt's --stats
# (parse + BVH + render, the image kept in memory and written to /dev/null's
# neighbour), plus the CPU seconds of one single-thread run, which machine
# load does not inflate. The target: the largest file
# (room_test3.rt) under 0.5 s.
# --minrt PATH times another build of minrt (default build/release/host/minrt).
# Usage: bench/host/minirt_speed.sh [--runs N] [--size WxH] [--shared DIR] [--minrt PATH]
. "$(dirname "$0")/../../scripts/help.sh"
. "$(dirname "$0")/speed_setup.sh"
set -euo pipefail
runs=5 size=1920x1080
speed_setup "--size size" -- "$@"
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
