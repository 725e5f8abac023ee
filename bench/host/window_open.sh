#!/usr/bin/env bash
# How long minrt's window takes to appear, and to go once ESC is pressed,
# under Xvfb: for each run, the seconds from starting `minrt SCENE.rt` (the
# miniRT window mode) until its window is viewable, then from the ESC key
# press (XTest) until the process has ended (test/host/x11_window.py
# measure: it starts minrt once connected to the X server and polls it
# every 5 ms). The render is slowed (MINRT_SHOW_ROW_DELAY_MS=200, 120
# rows: 24 s if it ran to the end) so that ESC always comes mid-render.
# Prints every run and the medians.
#
#   bench/host/window_open.sh [--runs N] [--minrt PATH]
#
# --minrt: the minrt binary (default build/release/host/minrt).
. "$(dirname "$0")/../../scripts/help.sh"
. "$(dirname "$0")/../../scripts/common.sh"
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
runs=5 minrt=$root/build/release/host/minrt
script_options "--runs runs" "--minrt minrt" -- "$@"
scene=${MINRT_SHARED_DIR:-$root/../shared}/formats/minirt/valid/showcase.rt
helper=$root/test/host/x11_window.py
# One X server for every run: what is measured is minrt, not Xvfb's start.
xvfb-run -a bash -s "$minrt" "$scene" "$helper" "$runs" <<'EOF'
set -euo pipefail
minrt=$1 scene=$2 helper=$3 runs=$4
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for ((i = 1; i <= runs; i++)); do
  read -r open quit status < <(cd "$work" && MINRT_SHOW_ROW_DELAY_MS=200 \
    python3 "$helper" measure "minrt: " -- "$minrt" --size 160x120 --threads 1 "$scene")
  [ "$status" = 0 ] || { echo "run $i: minrt exited with status $status" >&2; exit 1; }
  echo "run $i: window viewable after $open s; gone $quit s after ESC (exit status $status)"
  echo "$open $quit" >>"$work/times"
done
[ -z "$(ls "$work" | grep -v '^times$')" ] || { echo "minrt wrote files: $(ls "$work")" >&2; exit 1; }
sort -n -k1 "$work/times" | awk '{a[NR]=$1} END {printf "median window viewable: %.3f s\n", a[int((NR+1)/2)]}'
sort -n -k2 "$work/times" | awk '{a[NR]=$2} END {printf "median gone after ESC: %.3f s\n", a[int((NR+1)/2)]}'
EOF
