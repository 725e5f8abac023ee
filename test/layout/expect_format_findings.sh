#!/usr/bin/env bash
# Runs the format-list checker on its fixture and expects exactly the two
# findings the fixture holds, and status 1.
set -u
out=$(python3 "$1" "$2" "$3" 2>&1); rc=$?
echo "$out"
[[ $rc -eq 1 ]] || { echo "expected status 1, got $rc"; exit 1; }
grep -q '^host/second_list.cpp:6: tells formats apart by FormatId' <<<"$out" || exit 1
grep -q '^host/second_list.cpp:7: names a format ("\.RT")' <<<"$out" || exit 1
[[ $(wc -l <<<"$out") -eq 2 ]] || { echo "expected two findings"; exit 1; }
echo "fixture: both second lists reported"
