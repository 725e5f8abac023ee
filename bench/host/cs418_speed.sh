#!/usr/bin/env bash
# CS418 speed on the host: ray-many (256x256, 10,000 spheres) parse, BVH and
# render times as medians of interleaved runs (specialised path, every
# feature compiled in, one thread, all threads), and with --large the wall
# and CPU seconds of each large scene of make_cs418_large.py (spheres,
# spiral, chair; 800x800) on every core, one run each (--large-aa N renders
# them with N samples a pixel instead of their own, for a quicker look).
# --minrt PATH times another build of minrt (default build/release/host/minrt).
# Usage: bench/host/cs418_speed.sh [--runs N] [--large] [--large-aa N] [--shared DIR] [--minrt PATH]
. "$(dirname "$0")/../../scripts/help.sh"
. "$(dirname "$0")/speed_setup.sh"
set -euo pipefail
runs=9 large=0 large_aa=
speed_setup "--large large=1" "--large-aa large_aa" -- "$@"
[ -z "$large_aa" ] || large=1
# One --stats line -> "parse bvh render" seconds.
times_of() { sed -n 's/.*parse \([0-9.]*\) s, BVH \([0-9.]*\) s, render \([0-9.]*\) s.*/\1 \2 \3/p'; }
median() { sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
scene=$shared/formats/cs418/ray-many.txt
declare -A col
variants=("specialised,1:--threads 1" "all-features,1:--threads 1 --all-features" "specialised,all:")
for ((i = 0; i < runs; i++)); do
  for v in "${variants[@]}"; do
    name=${v%%:*}
    # shellcheck disable=SC2086
    read -r p b r < <("$minrt" --stats ${v#*:} "$scene" -o "$work/many.png" 2>&1 | times_of)
    col[$name.parse]+="$p "
    col[$name.bvh]+="$b "
    col[$name.render]+="$r "
  done
done
echo "ray-many 256x256, medians of $runs interleaved runs (seconds):"
printf '  %-18s %8s %8s %8s %8s\n' variant parse bvh render total
for v in "${variants[@]}"; do
  name=${v%%:*}
  p=$(tr ' ' '\n' <<<"${col[$name.parse]}" | grep . | median)
  b=$(tr ' ' '\n' <<<"${col[$name.bvh]}" | grep . | median)
  r=$(tr ' ' '\n' <<<"${col[$name.render]}" | grep . | median)
  printf '  %-18s %8.4f %8.4f %8.4f %8.4f\n' "$name" "$p" "$b" "$r" "$(awk -v a="$p" -v b="$b" -v c="$r" 'BEGIN{print a+b+c}')"
done
if [ "$large" = 1 ]; then
  echo "large scenes, 800x800, every core (wall and CPU = user + system seconds):"
  for name in spheres spiral chair; do
    python3 "$root/bench/host/make_cs418_large.py" "$name" ${large_aa:+--aa "$large_aa"} > "$work/$name.txt"
    aa=$(sed -n 's/^aa //p' "$work/$name.txt")
    /usr/bin/time -f '%e %U %S' -o "$work/time" "$minrt" "$work/$name.txt" -o "$work/$name.png"
    read -r wall user sys < "$work/time"
    printf '  %-8s aa %-3s wall %7.2f s  CPU %7.2f s\n' "$name" "$aa" "$wall" "$(awk -v u="$user" -v s="$sys" 'BEGIN{print u+s}')"
  done
fi
