#!/usr/bin/env bash
# One Jaworski scene on the firmware in firmware-sim (raw protocol, UART from
# the scene file) against the host's float model with the same shims: the
# BMP bytes must be identical.
# Usage: jaworski_firmware_check.sh SIM FIRMWARE MINRT SCENE WORKDIR
set -euo pipefail
sim=$1 fw=$2 minrt=$3 scene=$4 work=$5
mkdir -p "$work"
name=$(basename "$scene" .txt)
"$sim" --uart-in "$scene" --uart-out "$work/$name-fw.bmp" "$fw"
"$minrt" -q --precision float --shims portable "$scene" -o "$work/$name-host.bmp"
cmp "$work/$name-fw.bmp" "$work/$name-host.bmp"
echo "$name: firmware BMP identical to the host float model"
