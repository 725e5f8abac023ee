#!/usr/bin/env bash
# back_mode 1 and 2 without input on the board (test/eastray/scenes/
# back_sky_disc.ray): host-send prints the scene's one warning and the
# board renders the sky behind. Under each mode the board's image is
# minrt's (--precision float --shims portable), which the host test
# (eastray-output: back_mode 1 and 2 without input) probes pixel by pixel;
# here mode 2 must be mode 0's image (the disc seen) and mode 1 must not
# (the disc hidden).
# Usage: eastray_back_sky_check.sh SIM FIRMWARE HOST_SEND MINRT IMAGE_COMPARE SCENE WORKDIR
set -euo pipefail
sim=$1 fw=$2 send=$3 minrt=$4 compare=$5 scene=$6 work=$7
mkdir -p "$work"
for mode in 0 1 2; do
  sed "s/^back_mode 1 0 0 0 ;/back_mode $mode 0 0 0 ;/" "$scene" >"$work/mode$mode.ray"
  grep -q "^back_mode $mode 0 0 0 ;" "$work/mode$mode.ray"
  rm -f "$work/fw$mode.png" "$work/host$mode.png"
  "$send" --sim-binary "$sim" --sim "$fw" "$work/mode$mode.ray" -o "$work/fw$mode.png" 2>"$work/err$mode.txt"
  "$minrt" -q --precision float --shims portable "$work/mode$mode.ray" -o "$work/host$mode.png"
  "$compare" --identical "$work/fw$mode.png" "$work/host$mode.png" >/dev/null
  warnings=$(grep -c 'warning: back_mode 1 and 2 composite the input image' "$work/err$mode.txt" || true)
  if [[ $mode == 0 ]]; then want=0; else want=1; fi
  if [[ $warnings != "$want" ]]; then
    echo "back_mode $mode: $warnings warnings from host-send, want $want:" >&2
    cat "$work/err$mode.txt" >&2
    exit 1
  fi
done
grep -q "mode1.ray:6:1: warning: back_mode" "$work/err1.txt"
"$compare" --identical "$work/fw2.png" "$work/fw0.png" >/dev/null
if "$compare" --identical "$work/fw1.png" "$work/fw0.png" >/dev/null 2>&1; then
  echo "back_mode 1 rendered the disc that back_mode 0 shows" >&2
  exit 1
fi
echo "back_sky_disc: one warning, the board's images minrt's; mode 2 is mode 0's, mode 1 hides the disc"
