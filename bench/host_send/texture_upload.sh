#!/usr/bin/env bash
# Texture uploads over a slow line: every CS418 scene of the shared set that
# names a texture goes through host-send to the firmware in firmware-sim,
# whose UART is paced at each baud rate (8N1, in simulated time), and the
# PNG that comes back must equal `minrt --precision float --shims portable`
# byte for byte. host-send sends by default only the texture tiles its own
# render of the scene reads (sparse textures). For each scene and rate it
# prints the texels, how many of them went, the bytes the host sent
# (texture preamble, filtered and deflated, plus the scene text), the
# upload's line time (bytes x 10 / baud: the simulated seconds the board
# spent receiving it), the same with every texel (--full-textures: its
# bytes from one unpaced run) and with the plain texels, the board's whole
# simulated time and the wall time of the run.
# Usage: bench/host_send/texture_upload.sh [--build DIR] [--shared DIR] [BAUD...]   (default 115200 921600)
. "$(dirname "$0")/../../scripts/help.sh"
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=$root/build/release
shared=$root/../shared
bauds=()
while [ $# -gt 0 ]; do
  case $1 in
    --build) build=$2; shift 2 ;;
    --shared) shared=$2; shift 2 ;;
    -*) echo "texture_upload.sh: error: unknown option '$1' (see --help)" >&2; exit 2 ;;
    *) bauds+=("$1"); shift ;;
  esac
done
[ ${#bauds[@]} -gt 0 ] || bauds=(115200 921600)
hs=$build/host/send/host-send
sim=$build/firmware_sim/firmware-sim
elf=$build/firmware/minrt-rv32imf.elf
minrt=$build/host/minrt
for f in "$hs" "$sim" "$minrt"; do
  [ -x "$f" ] || { echo "texture_upload.sh: error: $f not built" >&2; exit 1; }
done
[ -f "$elf" ] || { echo "texture_upload.sh: error: $elf not built" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# firmware-sim with --stats, its stderr kept for the UART byte counts.
cat > "$work/sim.sh" <<EOF
#!/usr/bin/env bash
exec "$sim" --stats "\$@" 2> >(tee "$work/stats.log" >&2)
EOF
chmod +x "$work/sim.sh"

# PNG width x height from its IHDR.
texels() {
  local w h
  read -r w h < <(od -An -tu1 -j16 -N8 "$1" | awk '{print $1*16777216+$2*65536+$3*256+$4, $5*16777216+$6*65536+$7*256+$8}')
  echo $((w * h * 3))
}

echo "CPU: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//'), $(nproc) cores"
printf '%-12s %8s %10s %10s %10s %10s %10s %10s %10s %8s %s\n' scene baud texels "texels sent" sent "line s" "whole s" \
  "plain s" "board s" "wall s" image
failed=0
for scene in "$shared"/formats/cs418/*.txt; do
  names=$(awk '$1 == "texture" && $2 != "none" {print $2}' "$scene" | sort -u)
  [ -n "$names" ] || continue
  name=$(basename "$scene" .txt)
  dir=$(dirname "$scene")
  total=0
  for t in $names; do total=$((total + $(texels "$dir/$t"))); done
  text=$(wc -c < "$scene")
  "$minrt" -q --precision float --shims portable "$scene" -o "$work/model.png"
  # Every texel (--full-textures): the bytes do not depend on the rate.
  "$hs" -q --full-textures --sim-binary "$work/sim.sh" --sim "$elf" "$scene" -o "$work/whole.png" 2> "$work/hs.log" || {
    echo "texture_upload.sh: $name with --full-textures: host-send failed: $(tail -1 "$work/hs.log")" >&2
    failed=1
    continue
  }
  whole=$(sed -n 's/^uart: [0-9]* bytes out, \([0-9]*\) bytes in$/\1/p' "$work/stats.log")
  for baud in "${bauds[@]}"; do
    start=$(date +%s.%N)
    if ! "$hs" --sim-binary "$work/sim.sh" --sim "$elf" -b "$baud" "$scene" -o "$work/board.png" 2> "$work/hs.log"; then
      echo "texture_upload.sh: $name at $baud baud: host-send failed: $(tail -1 "$work/hs.log")" >&2
      failed=1
      continue
    fi
    wall=$(echo "$(date +%s.%N) - $start" | bc)
    sent=$(sed -n 's/^uart: [0-9]* bytes out, \([0-9]*\) bytes in$/\1/p' "$work/stats.log")
    # host-send's summary: "textures: N of M texels sent, ..." when sparse.
    went=$(sed -n 's/^host-send: textures: \([0-9]*\) of [0-9]* texels sent.*/\1/p' "$work/hs.log")
    [ -n "$went" ] || went=$((total / 3))
    board=$(sed -n 's/^board time: \([0-9.]*\) s.*/\1/p' "$work/stats.log")
    same=equal
    cmp -s "$work/board.png" "$work/model.png" || { same=DIFFERS; failed=1; }
    # Plain: marker, count, and per texture name, size and texels; then the text.
    plain=$((2 + total + text))
    for t in $names; do plain=$((plain + 5 + ${#t})); done
    printf '%-12s %8s %10s %10s %10s %10.1f %10.1f %10.1f %10.1f %8.1f %s\n' "$name" "$baud" "$((total / 3))" "$went" \
      "$sent" "$(echo "$sent * 10 / $baud" | bc -l)" "$(echo "$whole * 10 / $baud" | bc -l)" \
      "$(echo "$plain * 10 / $baud" | bc -l)" "$board" "$wall" "$same"
  done
done
exit $failed
