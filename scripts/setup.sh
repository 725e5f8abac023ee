#!/usr/bin/env bash
# Installs what the build needs (Debian packages, only the missing ones, as
# root), configures build/release with the host-release preset and builds
# it. Safe to rerun: it builds only what changed.
#   scripts/setup.sh            every package and every target (scripts/test.sh)
#   scripts/setup.sh --render   only what scripts/render.sh runs: the render's
#                               packages, then host-send, firmware-sim and the
#                               default firmware (target render-tools)
. "$(dirname "$0")/help.sh"
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
render_only=false
case ${1:-} in
  "") ;;
  --render) render_only=true ;;
  *) echo "setup.sh: error: unknown argument '$1' (see scripts/setup.sh --help)" >&2; exit 2 ;;
esac
if [[ $# -gt 1 ]]; then
  echo "setup.sh: error: unknown argument '$2' (see scripts/setup.sh --help)" >&2
  exit 2
fi

# One package a line, so that changes to the lists merge cleanly.
# What the render builds: the host compiler and CMake, clang for the
# firmware, the libraries host-send links.
render_packages=(
  cmake
  make
  g++
  pkg-config
  ccache                    # rebuilds in other clones reuse objects
  clang
  lld
  llvm
  python3                   # the firmware's .bin/.hex/.coe/.mem files
  zlib1g-dev                # host-send deflates textures
  libpng-dev                # PNG output and textures
  libtiff-dev               # EASTRAY .tif output
  libusb-1.0-0-dev          # host-send --list: USB serial adapters' names
)
# The rest: the tests, the fuzzers, the other firmware, the man pages.
test_packages=(
  libclang-rt-14-dev        # sanitizers and libFuzzer
  catch2
  libsdl2-dev               # the live window
  xvfb                      # window tests without a display
  xauth
  gdb-multiarch             # the simulator's GDB stub test
  help2man                  # man pages
  man-db
  qemu-user
  qemu-system-misc
  gcc-riscv64-unknown-elf   # libgcc.a of the rv32im and rv32i firmware
  qemu-system-arm           # the Cortex-M port's test (runtime/cortex-m)
  valgrind
  verilator                 # the RTL harness (rtl/)
  strace                    # the minrt --sync test counts fsync calls
  time                      # GNU time: CPU seconds in bench/host/contest_speed.sh
  python3-matplotlib
)
packages=("${render_packages[@]}")
if ! $render_only; then packages+=("${test_packages[@]}"); fi
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
# before is undone here, by either form (docs/building.md). CI builds with
# warnings as errors; a user's build only shows them. Shared data elsewhere
# than ../shared: MINRT_SHARED_DIR in the environment.
options=()
if [[ ${CI:-} == true ]]; then options+=(-DMINRT_WERROR=ON); fi
if [[ -n ${MINRT_SHARED_DIR:-} ]]; then options+=("-DMINRT_SHARED_DIR=$MINRT_SHARED_DIR"); fi
echo "setup: configuring build/release (cmake --preset host-release ${options[*]})" >&2
cmake --preset host-release "${options[@]}" >/dev/null
if $render_only; then
  echo "setup: building host-send, firmware-sim and the default firmware with $(nproc) jobs (progress below)" >&2
  cmake --build --preset host-release -j "$(nproc)" --target render-tools
else
  echo "setup: building everything with $(nproc) jobs (a first build takes a few minutes; progress below)" >&2
  cmake --build --preset host-release -j "$(nproc)"
fi
echo "setup: build complete" >&2
