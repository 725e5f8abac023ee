#!/usr/bin/env bash
# One CS418 scene on the firmware in firmware-sim (raw protocol, UART from
# the scene file) against the host's float model with the same shims:
# decoded pixels must be identical, and the specialised path must give the
# same bytes as --all-features.
# Usage: cs418_firmware_check.sh SIM FIRMWARE MINRT IMAGE_COMPARE SCENE WORKDIR
set -euo pipefail
sim=$1 fw=$2 minrt=$3 compare=$4 scene=$5 work=$6
mkdir -p "$work"
name=$(basename "$scene" .txt)
"$sim" --uart-in "$scene" --uart-out "$work/$name-fw.png" "$fw"
"$minrt" -q --precision float --shims portable "$scene" -o "$work/$name-host.png"
"$compare" --identical "$work/$name-fw.png" "$work/$name-host.png" >/dev/null
"$sim" --uart-in "$scene" --uart-out "$work/$name-fw-all.png" "$fw" -- --all-features
cmp "$work/$name-fw.png" "$work/$name-fw-all.png"
echo "$name: firmware image identical to the host float model (and to --all-features)"
