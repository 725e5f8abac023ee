#!/usr/bin/env bash
# Sets up, builds and runs every test: installs what is missing (Debian
# packages, as root), builds with the host-release preset into
# build/release, then runs every test with ctest.
#   scripts/test.sh [CTEST OPTIONS]
# Options go to ctest, e.g. scripts/test.sh -R golden, scripts/test.sh -L fuzz,
# scripts/test.sh -LE fuzz (everything but the 60-second fuzz runs).
. "$(dirname "$0")/help.sh"
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/setup.sh"
cd "$root"
ctest --preset host-release -j "$(nproc)" "$@"
