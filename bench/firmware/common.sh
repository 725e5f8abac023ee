# Sourced by the scripts in bench/firmware: finds the build, the simulator,
# the firmware and the shared scenes.
#   MINRT_BUILD_DIR   build directory (default: build/release, the preset's, then build-fw, build)
#   MINRT_SHARED_DIR  shared test data (default: ../shared next to the repo)
#   MINRT_FIRMWARE    firmware ELF (default: $MINRT_BUILD_DIR/firmware/minrt-rv32imf.elf)
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
if [[ -z ${MINRT_BUILD_DIR:-} ]]; then
  for d in "$repo/build/release" "$repo/build-fw" "$repo/build"; do
    if [[ -x $d/firmware_sim/firmware-sim ]]; then MINRT_BUILD_DIR=$d; break; fi
  done
fi
: "${MINRT_BUILD_DIR:?no build with firmware-sim found; set MINRT_BUILD_DIR}"
: "${MINRT_SHARED_DIR:=$repo/../shared}"
: "${MINRT_FIRMWARE:=$MINRT_BUILD_DIR/firmware/minrt-rv32imf.elf}"
sim=$MINRT_BUILD_DIR/firmware_sim/firmware-sim
for f in "$sim" "$MINRT_FIRMWARE"; do
  [[ -e $f ]] || { echo "missing $f (build the firmware-sim and firmware targets)" >&2; exit 1; }
done
scene_path() {
  local p=$1
  [[ -e $p ]] || p=$MINRT_SHARED_DIR/scenes/$1
  [[ -e $p ]] || { echo "scene $1 not found (MINRT_SHARED_DIR=$MINRT_SHARED_DIR)" >&2; exit 1; }
  echo "$p"
}
