#!/bin/sh
# Writes accuracy.md and accuracy/*.png (the report docs/accuracy.md shows)
# into an output folder, by default build/reports/accuracy (printed at the
# end); --write-docs regenerates the tracked docs/accuracy.md and
# docs/accuracy/*.png instead (its figures include this run's timings).
# Builds accuracy-report (in build/release, the preset's folder), renders
# every scene of ../shared/scenes and sld/hard at 128x128 in every math
# variant, measures contest.sld on the firmware (build/release/firmware,
# build/release/firmware_sim) and under callgrind, and renders the course
# scenes on the rv32imf firmware under every FPU model file in
# bench/accuracy/fpu-models/ (firmware-sim --fpu-model).
# Environment: BUILD (default build/release), MINRT_SHARED_DIR (default
# ../shared), FW_BUILD (default build/release), JOBS (default 2), FIRMWARE_ISAS
# (default rv32imf,rv32im), NO_CACHE=1 to rerun the firmware even when its
# counts are cached in $BUILD/accuracy-work/firmware-cache (keyed by a hash of
# the simulator, ELF, scene, arguments and cycle/FPU model; the soft-float run
# takes minutes, the FPU-model renders several).
# Then (bench/accuracy/format_speed.py) the text formats' speed against error:
# every scene of ../shared/formats/{cs418,jaworski,minirt/valid,eastray} in
# every variant, three scenes per format under callgrind and on the rv32imf
# firmware (host-send --sim); --formats does only this part (a few minutes),
# replacing its section of the output folder's accuracy.md.
# --hard-cases (bench/accuracy/hard_cases.py) does only the hard cases of the
# text formats: every scene of test/hard/scenes in every variant and on the
# rv32imf firmware, replacing the section "Hard cases, per format" (seconds
# after the build).
# Needs Debian's python3-numpy, python3-matplotlib and python3-pil (run with /usr/bin/python3).
# Prints one progress line per step on stderr (step n of N, elapsed seconds).
#   [ENV=VALUE ...] bench/accuracy/run.sh [--formats | --hard-cases] [--out DIR | --write-docs]   (several minutes)
. "$(dirname "$0")/../../scripts/help.sh"
set -eu
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${BUILD:-$root/build/release}
shared=${MINRT_SHARED_DIR:-$root/../shared}
fw_build=${FW_BUILD:-$root/build/release}
jobs=${JOBS:-2}
out=$root/build/reports/accuracy
while [ $# -gt 0 ]; do
  case $1 in
    --out) out=${2:?$1 needs a folder}; shift 2 ;;
    --write-docs) out=$root/docs; write_docs=1; shift ;;
    --formats) formats_only=1; shift ;;
    --hard-cases) hard_only=1; shift ;;
    *) echo "run.sh: error: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
done

if [ ! -f "$build/CMakeCache.txt" ]; then
  if [ "$build" = "$root/build/release" ]; then
    (cd "$root" && cmake --preset host-release)
  else
    cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release
  fi
fi
mkdir -p "$out"
command=bench/accuracy/run.sh
for var in BUILD MINRT_SHARED_DIR FW_BUILD JOBS FIRMWARE_ISAS NO_CACHE; do
  eval "val=\${$var:-}"
  [ -n "$val" ] && command="$var=$val $command"
done
[ -n "${formats_only:-}" ] && command="$command --formats"
[ -n "${hard_only:-}" ] && command="$command --hard-cases"
[ -n "${write_docs:-}" ] && command="$command --write-docs"

# What the text formats' parts run: minrt and host-send from $build, the
# simulator and the rv32imf firmware from $fw_build.
build_text_format_tools() {
  echo "accuracy: building minrt and host-send in $build, firmware-sim and the firmware in $fw_build" >&2
  cmake --build "$build" --target minrt host-send -j "$jobs"
  cmake --build "$fw_build" --target firmware-sim firmware-rv32imf -j "$jobs"
}
# The text formats' speed against error.
formats() {
  build_text_format_tools
  /usr/bin/python3 "$root/bench/accuracy/format_speed.py" --minrt "$build/host/minrt" \
    --host-send "$build/host/send/host-send" --sim "$fw_build/firmware_sim/firmware-sim" \
    --elf "$fw_build/firmware/minrt-rv32imf.elf" --shared "$shared" --work "$build/accuracy-work/formats" \
    --doc "$out/accuracy.md" --jobs "$jobs" --command "$command"
}
# The hard cases of the text formats.
hard_cases() {
  build_text_format_tools
  /usr/bin/python3 "$root/bench/accuracy/hard_cases.py" --minrt "$build/host/minrt" \
    --host-send "$build/host/send/host-send" --sim "$fw_build/firmware_sim/firmware-sim" \
    --elf "$fw_build/firmware/minrt-rv32imf.elf" --work "$build/accuracy-work/hard-cases" \
    --doc "$out/accuracy.md" --jobs "$jobs" --command "$command"
}
if [ -n "${formats_only:-}" ]; then
  formats
  exit
fi
if [ -n "${hard_only:-}" ]; then
  hard_cases
  exit
fi

echo "accuracy: building accuracy-report in $build" >&2
cmake --build "$build" --target accuracy-report -j "$jobs"
set -- --tool "$build/tools/accuracy/accuracy-report" --root "$root" --shared "$shared" \
  --work "$build/accuracy-work" --out "$out" --jobs "$jobs" --command "$command" \
  --firmware-isas "${FIRMWARE_ISAS:-rv32imf,rv32im}"
[ "${NO_CACHE:-0}" = 1 ] && set -- "$@" --no-cache
if [ -x "$fw_build/firmware_sim/firmware-sim" ]; then
  set -- "$@" --sim "$fw_build/firmware_sim/firmware-sim" --firmware-dir "$fw_build/firmware"
else
  echo "run.sh: no $fw_build/firmware_sim/firmware-sim: firmware counts left out" >&2
fi
status=0
/usr/bin/python3 "$root/bench/accuracy/make_report.py" "$@" || status=$?
formats || status=$?
hard_cases || status=$?
exit $status
