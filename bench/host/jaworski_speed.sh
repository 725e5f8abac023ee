#!/usr/bin/env bash
# Speed of minrt against Michał Jaworski's original program (JaworWr/Ray-tracer,
# built by hand outside this repository: pass its binary) on the issue's scene:
# 640x480, 20 spheres, a mirror floor, 2 lights, ray depth 4
# (bench/host/make_jaworski_scene.py).
#   bench/host/jaworski_speed.sh [--runs N] [--minrt BINARY] ORIGINAL_BINARY [ORIGINAL RTS OPTIONS...]
# e.g. bench/host/jaworski_speed.sh /work/ext/jaworski/ray-tracer +RTS -N -RTS
# Checks first that both write the same BMP, byte for byte; then runs minrt on
# one thread, minrt on every core and the original in turn, N times each,
# and prints the medians of the wall and CPU times (user + system, from
# bash's time), the ratios to the original and what every core gives over
# one thread. --minrt: the minrt to measure (default build/release/host/minrt).
# The load average is printed before and after the runs: the cores' gain is
# a wall-time figure and means something only on an idle machine (load
# well under 1); on a loaded one the CPU times are the steadier measure, a
# short run's wall time being mostly waiting for a core.
. "$(dirname "$0")/../../scripts/help.sh"
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
runs=7
minrt=$root/build/release/host/minrt
usage() { echo "usage: $0 [--runs N] [--minrt BINARY] ORIGINAL_BINARY [ORIGINAL OPTIONS...]" >&2; exit 2; }
while (($#)); do
  case $1 in
    --runs) [[ $# -ge 2 ]] || usage; runs=$2; shift 2 ;;
    --minrt) [[ $# -ge 2 ]] || usage; minrt=$2; shift 2 ;;
    *) break ;;
  esac
done
(($# >= 1)) || usage
original=$1
shift
original_opts=("$@")
[[ -x $minrt ]] || { echo "not built: $minrt (scripts/setup.sh builds it)" >&2; exit 1; }
[[ -x $original ]] || { echo "not an executable: $original" >&2; exit 1; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
python3 "$root/bench/host/make_jaworski_scene.py" >"$work/scene.txt"

# Same bytes first (the original prints its errors on stdout and exits 0,
# so a missing file is the sign of trouble).
"$original" "${original_opts[@]}" -o "$work/original.bmp" "$work/scene.txt" >"$work/original.log"
[[ -s $work/original.bmp ]] || { echo "the original wrote no image:" >&2; cat "$work/original.log" >&2; exit 1; }
"$minrt" -q --threads 1 -o "$work/minrt.bmp" "$work/scene.txt"
if ! cmp -s "$work/original.bmp" "$work/minrt.bmp"; then
  echo "the BMPs differ: $(cmp "$work/original.bmp" "$work/minrt.bmp" | head -1)" >&2
  exit 1
fi
echo "same BMP: sha256 $(sha256sum "$work/minrt.bmp" | cut -c1-16)... ($(stat -c %s "$work/minrt.bmp") bytes)"

# command... ; prints "wall cpu" seconds (cpu: user + system), to the millisecond
seconds() {
  local t TIMEFORMAT='%3R %3U %3S'
  t=$( { time "$@" >/dev/null 2>/dev/null; } 2>&1)
  awk '{printf "%.3f %.3f\n", $1, $2 + $3}' <<<"$t"
}
median() { sort -g | awk '{a[NR]=$1} END{print (NR%2) ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2}'; }

load_before=$(cut -d' ' -f1-3 /proc/loadavg)
declare -A wall cpu
names=(one all theirs)
for ((i = 0; i < runs; i++)); do
  for name in "${names[@]}"; do
    case $name in
      one) r=$(seconds "$minrt" -q --threads 1 -o "$work/a.bmp" "$work/scene.txt") ;;
      all) r=$(seconds "$minrt" -q -o "$work/b.bmp" "$work/scene.txt") ;;
      theirs) r=$(seconds "$original" "${original_opts[@]}" -o "$work/c.bmp" "$work/scene.txt") ;;
    esac
    wall[$name]+="${r% *} "
    cpu[$name]+="${r#* } "
  done
done
med() { tr ' ' '\n' <<<"$1" | grep . | median; }
cpu_model=$(awk -F': ' '/^model name/ {print $2; exit}' /proc/cpuinfo)
printf 'cpu: %s, %s cores; load average %s before the runs, %s after\n' "$cpu_model" "$(nproc)" "$load_before" \
  "$(cut -d' ' -f1-3 /proc/loadavg)"
printf '640x480, 20 spheres, 2 lights, ray depth 4; medians of %d interleaved runs (seconds)\n' "$runs"
printf '  %-26s %8s %8s   %s\n' program wall cpu 'wall times'
label() {
  case $1 in
    one) echo "minrt, 1 thread" ;;
    all) echo "minrt, $(nproc) threads" ;;
    theirs) echo "original ${original_opts[*]:-}" ;;
  esac
}
for name in "${names[@]}"; do
  printf '  %-26s %8.3f %8.3f   [%s]\n' "$(label "$name")" "$(med "${wall[$name]}")" "$(med "${cpu[$name]}")" "${wall[$name]% }"
done
awk -v tw="$(med "${wall[theirs]}")" -v tc="$(med "${cpu[theirs]}")" \
  -v ow="$(med "${wall[one]}")" -v oc="$(med "${cpu[one]}")" -v aw="$(med "${wall[all]}")" \
  -v ac="$(med "${cpu[all]}")" \
  'BEGIN{printf "  ratio, wall: original / minrt 1 thread %.1fx, / minrt all cores %.1fx\n", tw / ow, tw / aw;
         printf "  ratio, cpu:  original / minrt 1 thread %.1fx\n", tc / oc;
         printf "  all cores / 1 thread, wall: %.2fx (all cores use %.2fx the cpu)\n", ow / aw, ac / oc}'
