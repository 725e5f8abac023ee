#!/usr/bin/env bash
# Runs one libFuzzer target (or all) for a while on a copy of its seed corpus.
#   scripts/fuzz.sh [TARGET|all] [SECONDS]      (default: all, 600 s each)
# Targets: the fuzz_* binaries built under build/release/fuzz (the normal
# build makes them when clang has libFuzzer). New inputs the fuzzer finds
# stay in the copy (printed at the end); crashes are written to the current
# folder as crash-*; the seed corpus in fuzz/corpus is never modified.
. "$(dirname "$0")/help.sh"
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
target=${1:-all}
seconds=${2:-600}
bin=${MINRT_FUZZ_BIN:-$root/build/release/fuzz}
if [[ $target == all ]]; then
  targets=$(cd "$root/fuzz/corpus" && ls)
else
  targets=$target
fi
for t in $targets; do
  exe=$bin/fuzz_$t
  if [[ ! -x $exe ]]; then
    echo "fuzz: error: $exe is not built (is clang's libFuzzer installed? libclang-rt-14-dev)" >&2
    exit 2
  fi
  work=$(mktemp -d "${TMPDIR:-/tmp}/minrt-fuzz-$t.XXXXXX")
  cp -r "$root/fuzz/corpus/$t/." "$work/"
  echo "fuzz: $t for $seconds s, corpus $work"
  status=0
  "$exe" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 "$work" || status=$?
  if (( status != 0 )); then
    # The input that failed, in the log too: a CI run keeps only its output.
    for f in crash-* leak-* timeout-* oom-*; do
      [[ -f $f && $f -nt $work ]] || continue
      echo "fuzz: $t failed on $PWD/$f ($(stat -c %s "$f") bytes; first 1 KiB):" >&2
      head -c 1024 "$f" | od -A d -c >&2
    done
    exit "$status"
  fi
done
