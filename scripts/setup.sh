#!/usr/bin/env bash
# Installs what the build needs (Debian packages, only the missing ones, as
# root) and builds everything with the host-release preset. Safe to rerun.
#   scripts/setup.sh   (no arguments)
. "$(dirname "$0")/help.sh"
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
case ${1:-} in
  "") ;;
  *) echo "setup.sh: error: unknown argument '$1' (see scripts/setup.sh --help)" >&2; exit 2 ;;
esac

# One package a line, so that changes to the list merge cleanly.
packages=(
  cmake make g++ pkg-config
  ccache                    # rebuilds in other clones reuse objects
  clang lld llvm
  libclang-rt-14-dev        # sanitizers and libFuzzer
  catch2
  libusb-1.0-0-dev
  zlib1g-dev libpng-dev     # PNG output and textures
  libtiff-dev               # EASTRAY .tif output
  libsdl2-dev               # the live window
  xvfb xauth                # window tests without a display
  gdb-multiarch             # the simulator's GDB stub test
  help2man man-db           # man pages
  qemu-user qemu-system-misc gcc-riscv64-unknown-elf
  qemu-system-arm           # the Cortex-M port's test (runtime/cortex-m)
  valgrind
  verilator                 # the RTL harness (rtl/)
  strace                    # the minrt --sync test counts fsync calls
  time                      # GNU time: CPU seconds in bench/host/contest_speed.sh
  python3 python3-matplotlib
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "setup: installing ${#missing[@]} Debian packages: ${missing[*]}" >&2
  if [[ $(id -u) -ne 0 ]]; then
    echo "setup: need root to install packages (run with sudo)" >&2
    exit 1
  fi
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
  echo "setup: packages installed" >&2
else
  echo "setup: all ${#packages[@]} Debian packages present" >&2
fi

cd "$root"
# The preset sets every option, so a -D given to build/release by hand
# before is undone here (docs/building.md). CI builds with warnings as
# errors; a user's build only shows them. Shared data elsewhere than
# ../shared: MINRT_SHARED_DIR in the environment.
options=()
if [[ ${CI:-} == true ]]; then options+=(-DMINRT_WERROR=ON); fi
if [[ -n ${MINRT_SHARED_DIR:-} ]]; then options+=("-DMINRT_SHARED_DIR=$MINRT_SHARED_DIR"); fi
echo "setup: configuring build/release (cmake --preset host-release ${options[*]})" >&2
cmake --preset host-release "${options[@]}" >/dev/null
echo "setup: building with $(nproc) jobs (a first build takes a few minutes; progress below)" >&2
cmake --build --preset host-release -j "$(nproc)"
echo "setup: build complete" >&2
