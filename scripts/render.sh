#!/usr/bin/env bash
# Renders a scene end to end: installs the render's packages and builds what
# it runs (scripts/setup.sh --render: host-send, firmware-sim and the
# default firmware, nothing else), then sends SCENE to the embedded default
# (the RV32IMF firmware running in firmware-sim, over a pseudo-terminal)
# with host-send. Extra arguments go to host-send.
#   scripts/render.sh ../shared/scenes/contest.sld -o contest.ppm --size 128x128
. "$(dirname "$0")/help.sh"
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
if [[ $# -lt 1 ]]; then
  script_usage >&2
  exit 2
fi
# Set-up and build: their steps and the build's percentage are shown as they
# happen; the full output goes to a log, printed only when they fail.
log=$(mktemp)
set +e
"$root/scripts/setup.sh" --render 2>&1 | tee "$log" |
  grep --line-buffered -E '^setup:|^\[ *[0-9]+%\] (Built target|Linking|Performing build step|Training)' >&2
setup_status=${PIPESTATUS[0]}
set -e
if [[ $setup_status -ne 0 ]]; then
  cat "$log" >&2
  echo "render: set-up or build failed (log above)" >&2
  rm -f "$log"
  exit 1
fi
rm -f "$log"
exec "$root/build/release/host/send/host-send" --sim "$@"
