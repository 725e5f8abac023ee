#!/usr/bin/env bash
# Renders a scene end to end: sets up and builds, then sends SCENE to the
# embedded default (the RV32IMF firmware running in firmware-sim, over a
# pseudo-terminal) with host-send. Extra arguments go to host-send.
#   scripts/render.sh ../shared/scenes/contest.sld -o contest.ppm --size 128x128
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
if [[ $# -lt 1 || $1 == -h || $1 == --help ]]; then
  sed -n '2,5p' "$0" | sed 's/^# \{0,1\}//'
  exit 2
fi
# Set-up and build output go to a log; shown only when they fail.
log=$(mktemp)
if ! "$root/scripts/setup.sh" >"$log" 2>&1; then
  cat "$log" >&2
  echo "render: set-up or build failed (log above)" >&2
  exit 1
fi
rm -f "$log"
bin=$root/build/release
if [[ -x $bin/host/send/host-send ]]; then
  exec "$bin/host/send/host-send" "$@"
fi
echo "render: host-send is not built; rendering with the host build instead" >&2
exec "$bin/host/minrt" "$@"
