#!/usr/bin/env bash
# Runs a lock-step command that must stop at a divergence (status 9) and
# checks its report: every PATTERN (an extended regex) must match a line.
# The pattern "LOAD-BEFORE" instead checks that one of the last two
# instructions retired before the divergence was a load (a load-use bug
# shows in the instruction that consumes the load's register).
#   expect_divergence.sh PATTERN... -- COMMAND...
set -uo pipefail
patterns=()
while [[ $# -gt 0 && $1 != -- ]]; do patterns+=("$1"); shift; done
shift
out=$("$@" 2>&1 >/dev/null)
status=$?
printf '%s\n' "$out"
if [[ $status -ne 9 ]]; then
  echo "expect_divergence: status $status, expected 9 (a lock-step divergence)" >&2
  exit 1
fi
for p in "${patterns[@]}"; do
  if [[ $p == LOAD-BEFORE ]]; then
    if ! printf '%s\n' "$out" | grep -E '^    [0-9]+: ' | tail -n 2 | grep -q ' load 0x'; then
      echo "expect_divergence: no load among the last two instructions before the divergence" >&2
      exit 1
    fi
  elif ! printf '%s\n' "$out" | grep -Eq -- "$p"; then
    echo "expect_divergence: the report has no line matching '$p'" >&2
    exit 1
  fi
done
echo "expect_divergence: caught as expected"
