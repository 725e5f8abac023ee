#!/usr/bin/env bash
# Sets up, builds and runs every test (ctest, host-release preset).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/setup.sh"
cd "$root"
ctest --preset host-release -j "$(nproc)" "$@"
