#!/usr/bin/env bash
# Runs the layer checker on the fixture tree and expects exactly the two
# forbidden includes it contains to be reported, and a non-zero status.
set -u
out=$(python3 "$1" "$2" 2>&1); rc=$?
echo "$out"
[[ $rc -eq 1 ]] || { echo "expected status 1, got $rc"; exit 1; }
grep -q 'core/base/upward.hpp:3: error: core/ must not include "render/sld/tracer.hpp"' <<<"$out" || exit 1
grep -q 'protocol/wire.hpp:4: error: protocol/ must not include "core/math/math_policy.hpp"' <<<"$out" || exit 1
if grep -q 'fine.hpp' <<<"$out" || grep -q 'wire.hpp:3' <<<"$out"; then
  echo "an allowed include was reported"; exit 1
fi
echo "fixture: both forbidden includes reported, allowed ones not"
