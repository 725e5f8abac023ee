#!/usr/bin/env bash
# EASTRAY speed on the host: the three largest shared scenes (by bytes)
# and generated many-object scenes (bench/host/make_eastray_scene.py,
# --grid 10, 20 and 40 objects a side) in double and in the board's float
# arithmetic. Prints the median wall time of N interleaved runs on every
# core and the CPU seconds of the last run, then the median wall time on
# one thread (--threads 1) and what every core gives over one thread
# (ratio of the median wall times: a figure for an idle machine, the load
# average is printed). With --baseline PATH, an
# other minrt build is run in the same rounds; speed-up: the ratio of the
# median wall times.
# --minrt PATH times another build of minrt (default build/release/host/minrt).
# --fifo runs the script and everything it starts at real-time priority
# (SCHED_FIFO 10, as root), ahead of every ordinary process: on a machine
# other work keeps busy, the wall times are otherwise mostly waiting.
# Usage: bench/host/eastray_speed.sh [--runs N] [--baseline MINRT] [--shared DIR] [--minrt PATH] [--fifo]
. "$(dirname "$0")/../../scripts/help.sh"
. "$(dirname "$0")/speed_setup.sh"
set -euo pipefail
runs=3 baseline= fifo=0
speed_setup "--baseline baseline" "--fifo fifo=1" -- "$@"
if [ "$fifo" = 1 ] && ! chrt -f -p 10 $$ >/dev/null; then
  echo "eastray_speed.sh: error: --fifo: cannot run at real-time priority" >&2
  exit 1
fi
[ -z "$baseline" ] || [ -x "$baseline" ] || { echo "eastray_speed.sh: error: baseline '$baseline' is not an executable" >&2; exit 1; }
scenes=()
while read -r _ f; do scenes+=("$f"); done < <(for f in "$shared"/formats/eastray/*.ray; do echo "$(stat -c %s "$f") $f"; done | sort -rn | head -3)
for g in 10 20 40; do
  python3 "$root/bench/host/make_eastray_scene.py" --grid "$g" > "$work/grid$g.ray"
  scenes+=("$work/grid$g.ray")
done
# seconds (to the microsecond) and CPU seconds of one run: BIN SCENE PRECISION...
run() {
  local bin=$1 scene=$2 t0 t1
  shift 2
  t0=$EPOCHREALTIME
  /usr/bin/time -f "%U %S" -o "$work/time" "$bin" "$@" "$scene" -o "$work/img.png" 2>/dev/null
  t1=$EPOCHREALTIME
  awk -v t0="$t0" -v t1="$t1" '{printf "%.6f %s\n", t1 - t0, $1 + $2}' "$work/time"
}
median() { sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
declare -A wall cpu one bwall bcpu
precisions=("double" "float")
for ((r = 0; r < runs; r++)); do
  for s in "${scenes[@]}"; do
    for p in "${precisions[@]}"; do
      args=(--precision "$p")
      [ "$p" = float ] && args+=(--shims portable)
      key="$(basename "$s" .ray) $p"
      read -r w c < <(run "$minrt" "$s" "${args[@]}")
      wall[$key]="${wall[$key]:-} $w"
      cpu[$key]=$c
      read -r w c < <(run "$minrt" "$s" "${args[@]}" --threads 1)
      one[$key]="${one[$key]:-} $w"
      if [ -n "$baseline" ]; then
        read -r w c < <(run "$baseline" "$s" "${args[@]}")
        bwall[$key]="${bwall[$key]:-} $w"
        bcpu[$key]=$c
      fi
    done
  done
done
echo "load $(cut -d' ' -f1 /proc/loadavg) after the runs"
if [ -n "$baseline" ]; then
  printf "%-28s %-7s %8s %7s %9s %6s %10s %9s %8s\n" scene arith wall cpu "1 thread" cores "base wall" "base cpu" speedup
else
  printf "%-28s %-7s %8s %7s %9s %6s\n" scene arith wall cpu "1 thread" cores
fi
for s in "${scenes[@]}"; do
  for p in "${precisions[@]}"; do
    key="$(basename "$s" .ray) $p"
    m=$(echo "${wall[$key]}" | tr ' ' '\n' | grep . | median)
    o=$(echo "${one[$key]}" | tr ' ' '\n' | grep . | median)
    gain=$(awk -v a="$o" -v b="$m" 'BEGIN {print (b > 0 ? a / b : 0)}')
    if [ -n "$baseline" ]; then
      b=$(echo "${bwall[$key]}" | tr ' ' '\n' | grep . | median)
      printf "%-28s %-7s %7.3fs %6.2fs %8.3fs %5.2fx %9.3fs %8.2fs %7.1fx\n" "$(basename "$s")" "$p" "$m" "${cpu[$key]}" \
        "$o" "$gain" "$b" "${bcpu[$key]}" "$(awk -v a="$b" -v b="$m" 'BEGIN {print (b > 0 ? a / b : 0)}')"
    else
      printf "%-28s %-7s %7.3fs %6.2fs %8.3fs %5.2fx\n" "$(basename "$s")" "$p" "$m" "${cpu[$key]}" "$o" "$gain"
    fi
  done
done
