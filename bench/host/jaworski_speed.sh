#!/usr/bin/env bash
# Speed of minrt against Michał Jaworski's original program (JaworWr/Ray-tracer,
# built by hand outside this repository: pass its binary) on the issue's scene:
# 640x480, 20 spheres, a mirror floor, 2 lights, ray depth 4
# (bench/host/make_jaworski_scene.py).
#   bench/host/jaworski_speed.sh [--runs N] ORIGINAL_BINARY [ORIGINAL RTS OPTIONS...]
# e.g. bench/host/jaworski_speed.sh /work/ext/jaworski/ray-tracer +RTS -N -RTS
# Checks first that both write the same BMP, byte for byte; then runs minrt on
# one thread, minrt on every core and the original in turn, N times each,
# and prints the medians of the wall times and the ratios.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
runs=7
usage() { echo "usage: $0 [--runs N] ORIGINAL_BINARY [ORIGINAL OPTIONS...]" >&2; exit 2; }
while (($#)); do
  case $1 in
    --runs) [[ $# -ge 2 ]] || usage; runs=$2; shift 2 ;;
    -h | --help) usage ;;
    *) break ;;
  esac
done
(($# >= 1)) || usage
original=$1
shift
original_opts=("$@")
minrt=$root/build/release/host/minrt
[[ -x $minrt ]] || { echo "build first: scripts/setup.sh" >&2; exit 1; }
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

seconds() {  # command... ; prints wall seconds
  local t0 t1
  t0=$(date +%s.%N)
  "$@" >/dev/null
  t1=$(date +%s.%N)
  awk -v a="$t0" -v b="$t1" 'BEGIN{printf "%.4f\n", b - a}'
}
median() { sort -g | awk '{a[NR]=$1} END{print (NR%2) ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2}'; }

one=() all=() theirs=()
for ((i = 0; i < runs; i++)); do
  one+=("$(seconds "$minrt" -q --threads 1 -o "$work/a.bmp" "$work/scene.txt")")
  all+=("$(seconds "$minrt" -q -o "$work/b.bmp" "$work/scene.txt")")
  theirs+=("$(seconds "$original" "${original_opts[@]}" -o "$work/c.bmp" "$work/scene.txt")")
done
m_one=$(printf '%s\n' "${one[@]}" | median)
m_all=$(printf '%s\n' "${all[@]}" | median)
m_theirs=$(printf '%s\n' "${theirs[@]}" | median)
cpu=$(awk -F': ' '/^model name/ {print $2; exit}' /proc/cpuinfo)
printf 'cpu: %s, %s cores; load average %s\n' "$cpu" "$(nproc)" "$(cut -d' ' -f1-3 /proc/loadavg)"
printf '640x480, 20 spheres, 2 lights, ray depth 4; medians of %d interleaved runs (wall seconds)\n' "$runs"
printf '  minrt, 1 thread        %.4f  [%s]\n' "$m_one" "${one[*]}"
printf '  minrt, %d threads       %.4f  [%s]\n' "$(nproc)" "$m_all" "${all[*]}"
printf '  original %-13s %.4f  [%s]\n' "${original_opts[*]:-}" "$m_theirs" "${theirs[*]}"
awk -v t="$m_theirs" -v a="$m_one" -v b="$m_all" \
  'BEGIN{printf "  ratio: original / minrt 1 thread %.1fx, / minrt all cores %.1fx\n", t / a, t / b}'
