#!/usr/bin/env bash
# One miniRT scene on the firmware, sent by host-send to firmware-sim (raw
# protocol, its textures in the preamble), against the host's float model
# with the same shims: the decoded pixels must be identical.
# Usage: minirt_firmware_check.sh HOST_SEND SIM FIRMWARE MINRT IMAGE_COMPARE SCENE SIZE WORKDIR
set -euo pipefail
send=$1 sim=$2 fw=$3 minrt=$4 compare=$5 scene=$6 size=$7 work=$8
mkdir -p "$work"
name=$(basename "$scene" .rt)
"$send" -q --sim "$fw" --sim-binary "$sim" --size "$size" "$scene" -o "$work/$name-fw.png"
"$minrt" --precision float --shims portable --size "$size" "$scene" -o "$work/$name-host.png"
"$compare" --identical "$work/$name-fw.png" "$work/$name-host.png" >/dev/null
echo "$name: firmware image identical to the host float model at $size"
