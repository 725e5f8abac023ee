#!/usr/bin/env bash
# A large generated EASTRAY scene on the board (bench/host/make_eastray_scene.py
# --grid 38: 1445 objects, 1987 primitives, near the board's 2048): the
# firmware must build its object hierarchy (the profile shows the hierarchy's
# walk, csg_nearest_object) and send the pixels of the host float model.
# Then --grid 40 (2201 primitives) must be refused with one located line,
# status 3 and no image. See docs/firmware.md, "EASTRAY scenes with many
# objects".
# Usage: eastray_large_scene_check.sh SIM FIRMWARE HOST_SEND MINRT IMAGE_COMPARE GENERATOR WORKDIR
set -euo pipefail
sim=$1 fw=$2 send=$3 minrt=$4 compare=$5 generator=$6 work=$7
mkdir -p "$work"
rm -f "$work"/large-* "$work"/over-*
fail() { echo "eastray_large_scene_check: $*" >&2; exit 1; }

python3 "$generator" --grid 38 --size 32x24 > "$work/large-grid38.ray"
# The simulator as host-send starts it, with a per-function profile of the run.
cat > "$work/large-sim.sh" <<WRAP
#!/bin/sh
exec "$sim" --profile-out "$work/large-grid38.callgrind" "\$@"
WRAP
chmod +x "$work/large-sim.sh"
"$send" -q --sim-binary "$work/large-sim.sh" --sim "$fw" "$work/large-grid38.ray" -o "$work/large-grid38-fw.png"
"$minrt" -q --precision float --shims portable "$work/large-grid38.ray" -o "$work/large-grid38-host.png"
"$compare" --identical "$work/large-grid38-fw.png" "$work/large-grid38-host.png" >/dev/null ||
  fail "grid 38: the board's image differs from the host float model"
grep -q csg_nearest_object "$work/large-grid38.callgrind" ||
  fail "grid 38: the board did not build its object hierarchy (every ray tested every object)"
echo "grid 38 (1445 objects): object hierarchy built on the board, image identical to the host float model"

python3 "$generator" --grid 40 --size 32x24 > "$work/over-grid40.ray"
status=0
"$send" -q --sim-binary "$sim" --sim "$fw" "$work/over-grid40.ray" -o "$work/over-grid40.png" 2> "$work/over-grid40.err" ||
  status=$?
[[ $status == 3 ]] || fail "grid 40: status $status, expected 3: $(cat "$work/over-grid40.err")"
[[ ! -e $work/over-grid40.png ]] || fail "grid 40: an image was written"
[[ $(wc -l < "$work/over-grid40.err") == 1 ]] || fail "grid 40: not one line: $(cat "$work/over-grid40.err")"
grep -Eq 'board reported an error: [0-9]+:[0-9]+: too many .* for the memory' "$work/over-grid40.err" ||
  fail "grid 40: unexpected message: $(cat "$work/over-grid40.err")"
echo "grid 40 (2201 primitives): refused with $(cat "$work/over-grid40.err")"
