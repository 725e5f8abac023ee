#!/usr/bin/env bash
# contest.sld side by side: minrt (double/libm, the exact mode) on one thread
# and on every core, the original min-rt and, when given, a C port of it.
# Nothing of the originals is built here: build them yourself outside this
# repository and pass their paths (docs/performance.md has the exact flags).
#
#   bench/host/contest_speed.sh [--runs N] [--size N] [--minrt PATH] [--original PATH]
#                               [--c-port PATH --c-port-conv PATH] [--no-callgrind]
#
# --minrt: the minrt binary (default build/release/host/minrt).
# --original: a native build of the original program; it reads the SLD text
#   on standard input and renders the size compiled into it (rt W H), which
#   must be --size (checked on the output's header).
# --c-port: keiichiw/min-rt-c's min-rt, which reads the scene as converted by
#   that project's conv (--c-port-conv); the conversion is done once, untimed.
# Runs alternate between the programs so machine noise hits all alike; the
# ratios are of the medians. Every output is checked to be the same bytes as
# minrt's. callgrind counts are for single runs (one thread).
. "$(dirname "$0")/../../scripts/help.sh"
. "$(dirname "$0")/../../scripts/common.sh"
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
runs=5 size=512 minrt=$root/build/release/host/minrt original="" cport="" cconv="" callgrind=1
usage() {
  echo "usage: $0 [--runs N] [--size N] [--minrt PATH] [--original PATH] [--c-port PATH --c-port-conv PATH] [--no-callgrind]" >&2
  exit 2
}
script_options "--runs runs" "--size size" "--minrt minrt" "--original original" "--c-port cport" \
  "--c-port-conv cconv" "--no-callgrind callgrind=0" -- "$@"
[[ $runs =~ ^[1-9][0-9]*$ && $size =~ ^[1-9][0-9]*$ ]] || usage
[[ -n $cport && -z $cconv ]] && { echo "--c-port needs --c-port-conv (its scene converter)" >&2; exit 2; }
scene=${MINRT_SHARED_DIR:-$root/../shared}/scenes/contest.sld
[[ -x $minrt ]] || { echo "build first: scripts/setup.sh" >&2; exit 1; }
[[ -f $scene ]] || { echo "missing $scene" >&2; exit 1; }
for p in "$original" "$cport" "$cconv"; do
  [[ -z $p || -x $p ]] || { echo "not an executable: $p" >&2; exit 1; }
done

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cores=$(nproc)

# name | input file | command...
names=(minrt-1 "minrt-$cores") inputs=("$scene" "$scene")
cmds=("$minrt --threads 1 --size ${size}x${size}" "$minrt --size ${size}x${size}")
if [[ -n $original ]]; then names+=(original); inputs+=("$scene"); cmds+=("$original"); fi
if [[ -n $cport ]]; then
  "$cconv" <"$scene" >"$tmp/contest.bin"
  names+=(c-port); inputs+=("$tmp/contest.bin"); cmds+=("$cport")
fi

# Same bytes from everyone (the comparison is void otherwise).
"$minrt" --threads 1 --size "${size}x${size}" <"$scene" >"$tmp/ref.ppm"
for i in "${!names[@]}"; do
  ${cmds[$i]} <"${inputs[$i]}" >"$tmp/out.ppm"
  cmp -s "$tmp/ref.ppm" "$tmp/out.ppm" || {
    echo "${names[$i]}: output differs from minrt's at ${size}x${size} ($(head -c 20 "$tmp/out.ppm" | head -2 | tr '\n' ' '))" >&2
    exit 1
  }
done

seconds() {  # input-file command... ; prints "wall cpu" seconds (cpu: user + system)
  # Wall time from bash's microsecond clock: time's %e has 10 ms steps, 2.5%
  # of a 0.4 s run.
  local input=$1 start end; shift
  start=$EPOCHREALTIME
  /usr/bin/time -f '%U %S' -o "$tmp/time" "$@" <"$input" >/dev/null
  end=$EPOCHREALTIME
  awk -v s="$start" -v e="$end" '{printf "%.3f %.3f\n", e - s, $1 + $2}' "$tmp/time"
}
median() { sort -g | awk '{a[NR]=$1} END{print (NR%2) ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2}'; }

declare -A times cpus
for ((r = 0; r < runs; r++)); do
  for i in "${!names[@]}"; do
    # shellcheck disable=SC2086
    read -r w c < <(seconds "${inputs[$i]}" ${cmds[$i]})
    times[$i]+="$w " cpus[$i]+="$c "
  done
done

cpu=$(awk -F': ' '/^model name/ {print $2; exit}' /proc/cpuinfo)
printf 'cpu: %s, %d cores; load average %s\n' "$cpu" "$cores" "$(cut -d' ' -f1-3 /proc/loadavg)"
printf 'contest.sld %sx%s, same bytes (sha256 %s), medians of %d interleaved runs:\n' \
  "$size" "$size" "$(sha256sum "$tmp/ref.ppm" | cut -c1-16)" "$runs"
declare -A med cmed
printf '  %-12s %8s %8s   %s\n' program wall cpu 'wall times of the runs'
for i in "${!names[@]}"; do
  med[$i]=$(tr ' ' '\n' <<<"${times[$i]}" | grep . | median)
  cmed[$i]=$(tr ' ' '\n' <<<"${cpus[$i]}" | grep . | median)
  printf '  %-12s %7.3fs %7.3fs   [%s]\n' "${names[$i]}" "${med[$i]}" "${cmed[$i]}" "${times[$i]% }"
done
ratio() { awk -v a="$1" -v b="$2" 'BEGIN{printf "%.2fx", a / b}'; }
printf 'speed-ups (wall; cpu for one thread):\n'
printf '  minrt-%d against minrt-1     %s\n' "$cores" "$(ratio "${med[0]}" "${med[1]}")"
for i in "${!names[@]}"; do
  ((i >= 2)) || continue
  printf '  minrt-1 against %-12s %s (cpu %s)\n' "${names[$i]}" "$(ratio "${med[$i]}" "${med[0]}")" \
    "$(ratio "${cmed[$i]}" "${cmed[0]}")"
  printf '  minrt-%d against %-12s %s\n' "$cores" "${names[$i]}" "$(ratio "${med[$i]}" "${med[1]}")"
done

if ((callgrind)); then
  printf 'instructions (callgrind, one run each):\n'
  declare -A ir
  for i in "${!names[@]}"; do
    ((i == 1)) && continue
    # shellcheck disable=SC2086
    ir[$i]=$(valgrind --tool=callgrind --callgrind-out-file="$tmp/cg.out" ${cmds[$i]} <"${inputs[$i]}" 2>&1 >/dev/null |
      awk '/Collected/ {print $NF}')
    printf '  %-12s %15s\n' "${names[$i]}" "${ir[$i]}"
  done
  for i in "${!names[@]}"; do
    if ((i >= 2)); then printf '  %s / minrt-1: %s\n' "${names[$i]}" "$(ratio "${ir[$i]}" "${ir[0]}")"; fi
  done
fi
