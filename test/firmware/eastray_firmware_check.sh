#!/usr/bin/env bash
# One EASTRAY scene end to end: host-send preprocesses it and sends it to the
# firmware in firmware-sim (raw protocol), which renders it in float with the
# portable shims and streams a PNG back; its pixels must equal those of the
# host's float model (minrt --precision float --shims portable).
# Usage: eastray_firmware_check.sh SIM FIRMWARE HOST_SEND MINRT IMAGE_COMPARE SCENE WORKDIR [PROTOCOL]
set -euo pipefail
sim=$1 fw=$2 send=$3 minrt=$4 compare=$5 scene=$6 work=$7 protocol=${8:-raw}
mkdir -p "$work"
name=$(basename "$scene" .ray)-$protocol
rm -f "$work/$name"-{fw,host}{,_r,_l}.png
"$send" -q --sim-binary "$sim" --sim "$fw" --protocol "$protocol" "$scene" -o "$work/$name-fw.png"
"$minrt" -q --precision float --shims portable "$scene" -o "$work/$name-host.png"
# rmode 1 (a stereo pair): both write NAME_r.png and NAME_l.png, not NAME.png.
if grep -Eq '^[[:space:]]*rmode[[:space:]]+1' "$scene"; then
  for side in r l; do
    [[ ! -e "$work/$name-fw.png" && ! -e "$work/$name-host.png" ]]
    "$compare" --identical "$work/$name-fw_$side.png" "$work/$name-host_$side.png" >/dev/null
  done
  echo "$name: both stereo images from the firmware over $protocol identical to the host float model"
  exit 0
fi
"$compare" --identical "$work/$name-fw.png" "$work/$name-host.png" >/dev/null
echo "$name: firmware image over $protocol identical to the host float model"
