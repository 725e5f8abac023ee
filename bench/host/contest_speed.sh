#!/usr/bin/env bash
# Render time and instruction count of the host build (double/libm) on
# contest.sld at 512x512, optionally side by side with a native build of the
# original program (pass its path; build it yourself, outside this repo).
#   bench/host/contest_speed.sh [--runs N] [--size N] [--original PATH] [--no-callgrind]
# Runs alternate between the two programs so machine noise hits both alike;
# the ratio is of the medians.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
runs=5 size=512 original="" callgrind=1
while (($#)); do
  case $1 in
    --runs) runs=$2; shift 2 ;;
    --size) size=$2; shift 2 ;;
    --original) original=$2; shift 2 ;;
    --no-callgrind) callgrind=0; shift ;;
    *) echo "usage: $0 [--runs N] [--size N] [--original PATH] [--no-callgrind]" >&2; exit 2 ;;
  esac
done
minrt=$root/build/release/host/minrt
scene=${MINRT_SHARED_DIR:-$root/../shared}/scenes/contest.sld
[[ -x $minrt ]] || { echo "build first: scripts/setup.sh" >&2; exit 1; }
[[ -f $scene ]] || { echo "missing $scene" >&2; exit 1; }

seconds() {  # stdin-file command... ; prints wall seconds
  local input=$1 t0 t1; shift
  t0=$(date +%s.%N); "$@" <"$input" >/dev/null; t1=$(date +%s.%N)
  awk -v a="$t0" -v b="$t1" 'BEGIN{printf "%.3f\n", b - a}'
}
median() { sort -g | awk '{a[NR]=$1} END{print (NR%2) ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2}'; }

ours=() theirs=()
for ((i = 0; i < runs; i++)); do
  ours+=("$(seconds "$scene" "$minrt" --size "${size}x${size}")")
  # The original reads the scene on stdin; as published it renders 512x512.
  [[ -n $original ]] && theirs+=("$(seconds "$scene" "$original")")
done
m_ours=$(printf '%s\n' "${ours[@]}" | median)
printf 'contest.sld %sx%s, %d runs\n' "$size" "$size" "$runs"
printf 'minrt (double/libm)  median %.3f s  [%s]\n' "$m_ours" "${ours[*]}"
if [[ -n $original ]]; then
  m_theirs=$(printf '%s\n' "${theirs[@]}" | median)
  printf 'original             median %.3f s  [%s]\n' "$m_theirs" "${theirs[*]}"
  awk -v a="$m_theirs" -v b="$m_ours" 'BEGIN{printf "speed-up             %.2fx\n", a / b}'
fi
if ((callgrind)); then
  count() {  # stdin-file command...
    local input=$1 out; shift
    out=$(mktemp)
    valgrind --tool=callgrind --callgrind-out-file="$out" "$@" <"$input" 2>&1 >/dev/null |
      awk '/Collected/ {print $NF}'
    rm -f "$out"
  }
  printf 'minrt instructions     %s\n' "$(count "$scene" "$minrt" --size "${size}x${size}")"
  if [[ -n $original ]]; then
    printf 'original instructions  %s\n' "$(count "$scene" "$original")"
  fi
fi
