#!/usr/bin/env bash
# minrt SCENE.rt (the miniRT window mode) under Xvfb: ESC and the close
# button (WM_DELETE_WINDOW) end the program in the middle of a render that
# would take a minute (every row slowed to 500 ms), with exit status 0 and no
# file written; q too. The X events come from test/host/x11_window.py.
# Usage: window_quit_check.sh MINRT SHARED_DIR WORKDIR
set -euo pipefail
minrt=$1 shared=$2 work=$3
helper=$(dirname "$0")/x11_window.py
scene=$shared/formats/minirt/valid/showcase.rt
rm -rf "$work"
mkdir -p "$work"
xvfb-run -a bash -s "$minrt" "$scene" "$helper" "$work" <<'EOF'
set -euo pipefail
minrt=$1 scene=$2 helper=$3 work=$4
for action in key close; do
  dir=$work/$action
  mkdir -p "$dir"
  (cd "$dir" && MINRT_SHOW_ROW_DELAY_MS=500 exec "$minrt" --size 160x120 --threads 1 "$scene") &
  pid=$!
  python3 "$helper" --pid "$pid" wait "minrt: " 30 >/dev/null
  start=$SECONDS
  python3 "$helper" --pid "$pid" "$action" "minrt: " >/dev/null
  status=0
  wait "$pid" || status=$?
  # 120 rows at 500 ms: the render alone would last a minute.
  elapsed=$((SECONDS - start))
  [ "$status" = 0 ] || { echo "$action: exit status $status, expected 0"; exit 1; }
  [ "$elapsed" -le 20 ] || { echo "$action: the program ran on for $elapsed s after the window was closed"; exit 1; }
  [ -z "$(ls -A "$dir")" ] || { echo "$action: files written: $(ls -A "$dir")"; exit 1; }
  echo "$action: minrt ended with status 0 after ${elapsed} s, nothing written"
done
EOF
