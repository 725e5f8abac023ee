#!/usr/bin/env bash
# Sets up, builds and runs every test (ctest, host-release preset).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
if [[ ${1:-} == -h || ${1:-} == --help ]]; then
  cat <<'USAGE'
usage: scripts/test.sh [CTEST OPTIONS]
Installs what is missing (Debian packages, as root), builds with the
host-release preset into build/release, then runs every test with ctest.
Options go to ctest, e.g. scripts/test.sh -R golden, scripts/test.sh -L fuzz,
scripts/test.sh -LE fuzz (everything but the 60-second fuzz runs).
USAGE
  exit 0
fi
"$root/scripts/setup.sh"
cd "$root"
ctest --preset host-release -j "$(nproc)" "$@"
