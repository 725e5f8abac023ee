#!/usr/bin/env bash
# The row threads under ThreadSanitizer: minrt built with the host-tsan
# preset renders a few shared scenes of each threaded path (SLD in double and
# in portable float, EASTRAY, CS418, Jaworski, miniRT) at small sizes on 2, 3
# and 7 threads; each image must equal the one-thread image byte for byte and
# TSan must report nothing (halt_on_error=1, exitcode=66: a race fails the
# run with status 66). Builds nothing: run it on a tree built with the preset.
# Usage: threads_check.sh MINRT SHARED_DIR WORKDIR
set -euo pipefail
minrt=$1 shared=$2 work=$3
export TSAN_OPTIONS="halt_on_error=1:exitcode=66${TSAN_OPTIONS:+:$TSAN_OPTIONS}"

# A binary without TSan would pass every check below without testing
# anything: refuse it.
if ! grep -q __tsan_init "$minrt"; then
  echo "threads_check: $minrt is not built with -fsanitize=thread (use the host-tsan preset)" >&2
  exit 1
fi
if [ ! -d "$shared/scenes" ]; then
  echo "threads_check: no shared test data in $shared: skipped" >&2
  exit 77
fi
mkdir -p "$work"
fails=0 runs=0

# check NAME EXT ARGS...: renders with --threads 1, 2, 3 and 7 into
# WORKDIR/NAME-tN.EXT and compares each with the one-thread file.
check() {
  local name=$1 ext=$2
  shift 2
  local t out status
  for t in 1 2 3 7; do
    out=$work/$name-t$t.$ext
    rm -f "$out"
    status=0
    "$minrt" -q --threads "$t" "$@" -o "$out" 2>"$work/$name-t$t.err" || status=$?
    runs=$((runs + 1))
    if [ "$status" -ne 0 ]; then
      echo "FAIL $name --threads $t: status $status$([ "$status" -eq 66 ] && echo ' (ThreadSanitizer report)')" >&2
      head -n 40 "$work/$name-t$t.err" >&2
      fails=$((fails + 1))
    elif grep -q ThreadSanitizer "$work/$name-t$t.err"; then
      echo "FAIL $name --threads $t: ThreadSanitizer wrote a report" >&2
      head -n 40 "$work/$name-t$t.err" >&2
      fails=$((fails + 1))
    elif [ "$t" -ne 1 ] && ! cmp -s "$work/$name-t1.$ext" "$out"; then
      echo "FAIL $name --threads $t: the image differs from the one-thread image" >&2
      fails=$((fails + 1))
    fi
  done
}

check contest ppm --size 64x64 --format p6 "$shared/scenes/contest.sld"
check contest-float ppm --size 48x48 --format p6 --precision float --shims portable "$shared/scenes/contest.sld"
check tron ppm --size 48x48 --format p6 "$shared/scenes/tron.sld"
check piero1 ppm --size 48x48 --format p6 "$shared/scenes/piero1.sld"
check eastray-csg png --size 64x48 "$shared/formats/eastray/csg_or_and_diff_range.ray"
check eastray-mesh png --size 64x48 "$shared/formats/eastray/kinds_20_polygon_mesh.ray"
check cs418 png "$shared/formats/cs418/ray-shadow-plane.txt"
check jaworski bmp "$shared/formats/jaworski/basic-diffuse-sphere.txt"
check minirt ppm --size 64x48 "$shared/formats/minirt/valid/complex.rt"

if [ "$fails" -ne 0 ]; then
  echo "threads_check: $fails of $runs runs failed" >&2
  exit 1
fi
echo "threads_check: $runs runs, every image equal to its one-thread image, no ThreadSanitizer report"
